#pragma once
/// \file module_factory.hpp
/// Builders of the optional modules that a scene asks for (e.g. heat conduction for a `thermal:` section),
/// registered by the module's register_module(). build_simulation() calls every builder once, after the
/// bodies are filled and before the simulation takes its first snapshot, so that a module can add its
/// particle fields; a builder returns nullptr when the scene does not use its module (then nothing is
/// constructed and nothing runs).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mpm/module.hpp"
#include "mpm/scene.hpp"

namespace mpm {

template <int Dim>
using SceneModuleBuilder = std::function<std::shared_ptr<Module<Dim>>(
    const SceneDescription& scene, std::vector<Body<Dim>>& bodies, const GridGeometry<Dim>& grid)>;

/// One module's builders, one per dimension.
struct SceneModuleFactory {
  std::string name;
  SceneModuleBuilder<1> build_1d;
  SceneModuleBuilder<2> build_2d;
  SceneModuleBuilder<3> build_3d;
};

/// Registers (or replaces, by name) a module's builders.
void register_scene_module(SceneModuleFactory factory);
/// The registered builders of dimension Dim, in registration order.
template <int Dim>
std::vector<SceneModuleBuilder<Dim>> scene_module_builders();

}  // namespace mpm
