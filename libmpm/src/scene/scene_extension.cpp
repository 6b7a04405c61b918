#include "mpm/scene/scene_extension.hpp"

#include <algorithm>

#include "mpm/core/kind_table.hpp"

namespace mpm {
namespace {

/// The registered sections (core/kind_table.hpp), listed by key.
KindTable<SceneExtension, &SceneExtension::key>& registry() {
  static KindTable<SceneExtension, &SceneExtension::key> table;
  return table;
}

/// The keys of `solver:` a scheme owns.
struct SchemeSolverKeys {
  std::string scheme;
  std::vector<io::KeySpec> keys;
};
KindTable<SchemeSolverKeys, &SchemeSolverKeys::scheme>& solver_key_registry() {
  static KindTable<SchemeSolverKeys, &SchemeSolverKeys::scheme> table;
  return table;
}

}  // namespace

void register_scene_extension(SceneExtension extension) { registry().add(std::move(extension)); }

const SceneExtension* find_scene_extension(const std::string& key) { return registry().find(key); }

std::vector<std::string> scene_extension_keys() {
  std::vector<std::string> keys = registry().names();
  std::sort(keys.begin(), keys.end());
  return keys;
}

void register_scheme_solver_keys(const std::string& scheme, std::vector<io::KeySpec> keys) {
  solver_key_registry().add({scheme, std::move(keys)});
}

std::vector<SchemeSolverKey> scheme_solver_keys() {
  std::vector<std::string> schemes = solver_key_registry().names();
  std::sort(schemes.begin(), schemes.end());
  std::vector<SchemeSolverKey> keys;
  for (const auto& scheme : schemes)
    for (const auto& spec : solver_key_registry().find(scheme)->keys) keys.push_back({spec, scheme});
  return keys;
}

template <int Dim>
std::vector<std::shared_ptr<Module<Dim>>> prepare_scene_extensions(const SceneDescription& scene,
                                                                   std::vector<Body<Dim>>& bodies,
                                                                   const GridGeometry<Dim>& grid) {
  std::vector<SceneExtension> extensions;  // in key order; copied: a preparer may register kinds of its own
  for (const auto& key : scene_extension_keys()) extensions.push_back(*find_scene_extension(key));
  std::vector<std::shared_ptr<Module<Dim>>> modules;
  for (const auto& e : extensions) {
    SectionPreparer<Dim> prepare = nullptr;
    if constexpr (Dim == 1) prepare = e.prepare_1d;
    if constexpr (Dim == 2) prepare = e.prepare_2d;
    if constexpr (Dim == 3) prepare = e.prepare_3d;
    if (!prepare) continue;
    if (auto m = prepare(scene, bodies, grid)) modules.push_back(std::move(m));
  }
  return modules;
}

template <int Dim>
void build_scene_extensions(const SceneDescription& scene, Simulation<Dim>& simulation) {
  for (const auto& [key, section] : scene.extensions) {
    const SceneExtension* e = find_scene_extension(key);
    if (!e) continue;
    SectionBuilder<Dim> build = nullptr;
    if constexpr (Dim == 1) build = e->build_1d;
    if constexpr (Dim == 2) build = e->build_2d;
    if constexpr (Dim == 3) build = e->build_3d;
    if (build) build(scene, simulation);
  }
}

template std::vector<std::shared_ptr<Module<1>>> prepare_scene_extensions<1>(const SceneDescription&,
                                                                             std::vector<Body<1>>&,
                                                                             const GridGeometry<1>&);
template std::vector<std::shared_ptr<Module<2>>> prepare_scene_extensions<2>(const SceneDescription&,
                                                                             std::vector<Body<2>>&,
                                                                             const GridGeometry<2>&);
template std::vector<std::shared_ptr<Module<3>>> prepare_scene_extensions<3>(const SceneDescription&,
                                                                             std::vector<Body<3>>&,
                                                                             const GridGeometry<3>&);
template void build_scene_extensions<1>(const SceneDescription&, Simulation<1>&);
template void build_scene_extensions<2>(const SceneDescription&, Simulation<2>&);
template void build_scene_extensions<3>(const SceneDescription&, Simulation<3>&);

}  // namespace mpm
