#include "mpm/scheme_extension.hpp"

#include <map>
#include <mutex>
#include <stdexcept>

namespace mpm {
namespace {

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::map<std::string, SchemeExtension>& registry() {
  static std::map<std::string, SchemeExtension> r;
  return r;
}

}  // namespace

void register_scheme_extension(SchemeExtension extension) {
  std::lock_guard lock(registry_mutex());
  registry()[extension.name] = std::move(extension);
}

const SchemeExtension* find_scheme_extension(const std::string& name) {
  std::lock_guard lock(registry_mutex());
  const auto it = registry().find(name);
  return it == registry().end() ? nullptr : &it->second;
}

std::vector<std::string> scheme_extension_names() {
  std::lock_guard lock(registry_mutex());
  std::vector<std::string> names;
  for (const auto& [name, e] : registry()) names.push_back(name);
  return names;
}

std::vector<std::pair<std::string, std::string>> scheme_extension_solver_keys() {
  std::lock_guard lock(registry_mutex());
  std::vector<std::pair<std::string, std::string>> keys;
  for (const auto& [name, e] : registry())
    for (const auto& key : e.solver_keys) keys.emplace_back(key, name);
  return keys;
}

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_extension_scheme(const SceneDescription& scene) {
  const SchemeExtension* e = find_scheme_extension(scene.solver.extension_scheme);
  if (!e) throw std::invalid_argument("unknown scheme '" + scene.solver.extension_scheme + "'");
  SchemeMaker<Dim> make = nullptr;
  if constexpr (Dim == 1) make = e->make_1d;
  if constexpr (Dim == 2) make = e->make_2d;
  if constexpr (Dim == 3) make = e->make_3d;
  if (!make) throw std::invalid_argument("scheme '" + e->name + "' is not available in " + std::to_string(Dim) + "D");
  return make(scene);
}

template std::unique_ptr<Scheme<1>> make_extension_scheme<1>(const SceneDescription&);
template std::unique_ptr<Scheme<2>> make_extension_scheme<2>(const SceneDescription&);
template std::unique_ptr<Scheme<3>> make_extension_scheme<3>(const SceneDescription&);

}  // namespace mpm
