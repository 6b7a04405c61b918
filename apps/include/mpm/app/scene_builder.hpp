#pragma once
/// \file scene_builder.hpp
/// Turns a validated scene description into a ready Simulation: grid, bodies filled with particles,
/// materials, scheme (dimension and shape function picked here, once), boundary conditions.

#include <memory>
#include <vector>

#include "mpm/scene/scene.hpp"
#include "mpm/simulation/gravity_stage.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm::app {

/// Throws SceneError (naming the key) for what only the built simulation can check: a scene whose memory estimate
/// exceeds what the machine has (memory_estimate.hpp, checked before anything is allocated), a body with no
/// particle, or a fixed dt above the stable time step (the message gives the bound).
/// With `solver.gravity_stage` and `gravity_stage` true, runs the stage (gravity_stage.hpp) before the energy books
/// are added and stores its report in `stage_report` (when not null); a stage that does not settle throws SceneError
/// at the key unless it says `on_no_equilibrium: warn`. A restart passes false: the checkpoint holds the settled
/// state.
template <int Dim>
std::unique_ptr<Simulation<Dim>> build_simulation(const SceneDescription& scene, bool gravity_stage = true,
                                                  GravityStageReport* stage_report = nullptr);

/// The scene's bodies without particles, each with its material and every on-demand particle field a run of the
/// scene adds to it (particle domains, APIC, hoop fields, output and history fields, the material's history, the
/// modules' prepare stage): ParticleSet::bytes_per_particle() of one is what a particle of the real body costs.
template <int Dim>
std::vector<Body<Dim>> prototype_bodies(const SceneDescription& scene, const GridGeometry<Dim>& geometry);

}  // namespace mpm::app
