#include "mpm/scene/scene_extension.hpp"

#include <map>
#include <mutex>

namespace mpm {
namespace {

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::map<std::string, SceneExtension>& registry() {
  static std::map<std::string, SceneExtension> r;
  return r;
}

}  // namespace

void register_scene_extension(SceneExtension extension) {
  std::lock_guard lock(registry_mutex());
  registry()[extension.key] = std::move(extension);
}

const SceneExtension* find_scene_extension(const std::string& key) {
  std::lock_guard lock(registry_mutex());
  const auto it = registry().find(key);
  return it == registry().end() ? nullptr : &it->second;
}

std::vector<std::string> scene_extension_keys() {
  std::lock_guard lock(registry_mutex());
  std::vector<std::string> keys;
  for (const auto& [key, e] : registry()) keys.push_back(key);
  return keys;
}

template <int Dim>
std::vector<std::shared_ptr<Module<Dim>>> prepare_scene_extensions(const SceneDescription& scene,
                                                                   std::vector<Body<Dim>>& bodies,
                                                                   const GridGeometry<Dim>& grid) {
  std::vector<SceneExtension> extensions;  // copied: a preparer may not hold the registry's lock
  {
    std::lock_guard lock(registry_mutex());
    for (const auto& [key, e] : registry()) extensions.push_back(e);
  }
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
