#include "mpm/scene_extension.hpp"

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

template void build_scene_extensions<1>(const SceneDescription&, Simulation<1>&);
template void build_scene_extensions<2>(const SceneDescription&, Simulation<2>&);
template void build_scene_extensions<3>(const SceneDescription&, Simulation<3>&);

}  // namespace mpm
