#include "mpm/schemes/scheme_registry.hpp"

#include <map>
#include <mutex>
#include <stdexcept>

#include "core_schemes.hpp"

namespace mpm {
namespace {

/// The registered schemes by name (a map, so that pointers handed out stay valid when schemes are added), and
/// their names in registration order.
struct Registry {
  std::map<std::string, SchemeSpec, std::less<>> specs;
  std::vector<std::string> order;

  void add(SchemeSpec spec) {
    const std::string name = spec.name;
    if (!specs.count(name)) order.push_back(name);
    specs.insert_or_assign(name, std::move(spec));
  }
};

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
Registry& registry() {
  static Registry r = [] {
    Registry core;
    for (auto& spec : core_schemes()) core.add(std::move(spec));
    return core;
  }();
  return r;
}

}  // namespace

void register_scheme(SchemeSpec spec) {
  std::lock_guard lock(registry_mutex());
  registry().add(std::move(spec));
}

const SchemeSpec* find_scheme(std::string_view name) {
  std::lock_guard lock(registry_mutex());
  const auto it = registry().specs.find(name);
  return it == registry().specs.end() ? nullptr : &it->second;
}

const SchemeSpec& scheme_of(const SolverDescription& solver) {
  if (const SchemeSpec* spec = find_scheme(solver.scheme)) return *spec;
  throw std::invalid_argument("unknown scheme '" + solver.scheme +
                              "' (valid: " + scheme_names_where([](const SchemeTraits&) { return true; }) + ")");
}

std::vector<std::string> scheme_names() {
  std::lock_guard lock(registry_mutex());
  return registry().order;
}

std::string scheme_names_where(const std::function<bool(const SchemeTraits&)>& accept) {
  std::vector<std::string> names;
  for (const auto& name : scheme_names())
    if (accept(find_scheme(name)->traits)) names.push_back(name);
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
  return text;
}

std::vector<std::pair<std::string, std::string>> scheme_solver_keys() {
  std::lock_guard lock(registry_mutex());
  std::vector<std::pair<std::string, std::string>> keys;
  for (const auto& name : registry().order)
    for (const auto& key : registry().specs.at(name).solver_keys) keys.emplace_back(key, name);
  return keys;
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
