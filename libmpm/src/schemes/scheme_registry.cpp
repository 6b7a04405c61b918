#include "mpm/schemes/scheme_registry.hpp"

#include <stdexcept>

#include "core_schemes.hpp"
#include "mpm/core/kind_table.hpp"

namespace mpm {
namespace {

/// The registered schemes, the core's first (core/kind_table.hpp).
KindTable<SchemeSpec>& registry() {
  static KindTable<SchemeSpec> table{[] {
    std::deque<SchemeSpec> core;
    for (auto& spec : core_schemes()) core.push_back(std::move(spec));
    return core;
  }()};
  return table;
}

}  // namespace

void register_scheme(SchemeSpec spec) { registry().add(std::move(spec)); }

const SchemeSpec* find_scheme(std::string_view name) { return registry().find(name); }

const SchemeSpec& scheme_of(const SolverDescription& solver) {
  if (const SchemeSpec* spec = find_scheme(solver.scheme)) return *spec;
  throw std::invalid_argument("unknown scheme '" + solver.scheme +
                              "' (valid: " + scheme_names_where([](const SchemeTraits&) { return true; }) + ")");
}

std::vector<std::string> scheme_names() { return registry().names(); }

std::string scheme_names_where(const std::function<bool(const SchemeTraits&)>& accept) {
  std::vector<std::string> names;
  for (const auto& name : scheme_names())
    if (accept(find_scheme(name)->traits)) names.push_back(name);
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
  return text;
}

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_scene_scheme(const SceneDescription& scene) {
  const SchemeSpec& spec = scheme_of(scene.solver);
  const SchemeMaker<Dim> make = spec.maker<Dim>();
  if (!make) throw std::invalid_argument("scheme '" + spec.name + "' is not available in " + std::to_string(Dim) + "D");
  return make(scene);
}

template std::unique_ptr<Scheme<1>> make_scene_scheme<1>(const SceneDescription&);
template std::unique_ptr<Scheme<2>> make_scene_scheme<2>(const SceneDescription&);
template std::unique_ptr<Scheme<3>> make_scene_scheme<3>(const SceneDescription&);

}  // namespace mpm
