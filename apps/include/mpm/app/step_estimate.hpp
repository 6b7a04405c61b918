#pragma once
/// \file step_estimate.hpp
/// How many steps and how much wall time a scene asks for, from the time step of its initial state, and which key
/// sets that time step: a typo that collapses it (`density: 1e-9`, a velocity of 1e200 m/s) otherwise shows only as
/// a run that never ends. `mpm check` and the start of `mpm run` warn above the thresholds of scene_limits.hpp; a
/// time step of 0, infinity or one too small to advance the time at end_time is refused when the simulation is
/// built (docs/scene-reference.md, "Limits").

#include <string>

#include "mpm/scene/scene.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm::app {

struct StepEstimate {
  double dt = 0;            ///< s, the first step's
  double steps = 0;         ///< end_time / dt
  double wall_seconds = 0;  ///< steps x particles / assumed_particle_updates_per_second
  std::string key;          ///< the key that sets the governing bound (empty when no single key does)
  SourceLocation where;     ///< its place in the scene file
  std::string reason;       ///< what governs, with its numbers
};

/// The estimate for the simulation built from `scene`, before its first step.
template <int Dim>
StepEstimate estimate_steps(const SceneDescription& scene, const Simulation<Dim>& sim);

/// The warning (`FILE:LINE:COLUMN: KEY: message`) when the estimate is above a threshold, else "".
std::string step_warning(const StepEstimate& estimate);

/// Throws SceneError at the governing key when the time step is 0, not finite, or so small against end_time that
/// the time could not advance (end_time + dt == end_time in double precision).
void check_time_step(const StepEstimate& estimate, const SceneDescription& scene);

}  // namespace mpm::app
