#pragma once
/// \file scene_limits.hpp
/// The documented bounds a scene is held to beyond its values' physical ranges (docs/scene-reference.md, "Limits"):
/// what keeps a typo from running without end or asking for more memory than the machine has.

namespace mpm {

/// The most particles per cell a body may ask for on one axis (`bodies[].particles_per_cell`, `mpm particles
/// --ppc`): 100 per axis is 1e4 per cell in 2D and 1e6 in 3D, far beyond what convergence studies use (1-8); the
/// lattice fill of a single 3D cell at 1e6 per axis (a typo) would visit 1e18 points.
inline constexpr int max_particles_per_cell = 100;

/// Estimated steps above which `mpm check` and the start of `mpm run` warn (the time step was probably collapsed by
/// a typo: a density, a velocity, a cell size).
inline constexpr double step_count_warning = 1e7;
/// Estimated wall seconds above which they warn, at `assumed_particle_updates_per_second`.
inline constexpr double wall_time_warning = 1e6;
/// The rate of the wall-time estimate: particle-updates per second of this machine's 2 cores on a linear-hat
/// scene (docs/PERFORMANCE.md, bench_throughput on 2 threads: 2.9-3.9e7 in 2D, 1.3-1.6e7 in 3D; cubic B-splines
/// 2.4e6-1.2e7; plasticity slower).
inline constexpr double assumed_particle_updates_per_second = 1e7;

}  // namespace mpm
