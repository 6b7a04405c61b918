#pragma once
/// \file scene_builder.hpp
/// Turns a validated scene description into a ready Simulation: grid, bodies filled with particles,
/// materials, scheme (dimension and shape function picked here, once), boundary conditions.

#include <memory>

#include "mpm/scene.hpp"
#include "mpm/simulation.hpp"

namespace mpm::app {

/// Throws SceneError (naming the key) for what only the built simulation can check: a body with no
/// particle, or a fixed dt above the stable time step (the message gives the bound).
template <int Dim>
std::unique_ptr<Simulation<Dim>> build_simulation(const SceneDescription& scene);

}  // namespace mpm::app
