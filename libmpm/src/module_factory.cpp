#include "mpm/module_factory.hpp"

namespace mpm {
namespace {

std::vector<SceneModuleFactory>& factories() {
  static std::vector<SceneModuleFactory> list;
  return list;
}

}  // namespace

void register_scene_module(SceneModuleFactory factory) {
  for (auto& f : factories())
    if (f.name == factory.name) {
      f = std::move(factory);
      return;
    }
  factories().push_back(std::move(factory));
}

template <int Dim>
std::vector<SceneModuleBuilder<Dim>> scene_module_builders() {
  std::vector<SceneModuleBuilder<Dim>> builders;
  for (const auto& f : factories()) {
    if constexpr (Dim == 1)
      builders.push_back(f.build_1d);
    else if constexpr (Dim == 2)
      builders.push_back(f.build_2d);
    else
      builders.push_back(f.build_3d);
  }
  return builders;
}

template std::vector<SceneModuleBuilder<1>> scene_module_builders<1>();
template std::vector<SceneModuleBuilder<2>> scene_module_builders<2>();
template std::vector<SceneModuleBuilder<3>> scene_module_builders<3>();

}  // namespace mpm
