#pragma once
/// \file strength_reduction.hpp
/// Slope stability by strength reduction (issue 52; bench/strength_reduction.py is the same case from the command
/// line): Griffiths & Lane (1999), example 1, a homogeneous slope with no foundation layer (depth factor D = 1),
/// H = 10 m, 2:1 (26.57 deg), a crest 1.2 H wide: the trapezoid (0, 0), (32, 0), (12, 10), (0, 10) in m, plane
/// strain, rollers behind (x_min: slip), a rough base at the toe (y_min: fixed). Mohr-Coulomb, rho = 2000 kg/m^3,
/// g = 10 m/s^2 (gamma = 20 kN/m^3), E = 100 MPa, nu = 0.3, c = 0.05 gamma H = 10 kPa, phi = 20 deg, psi = 0, tension
/// up to the apex c cot(phi). Their finite-element factor of safety is 1.4, Bishop & Morgenstern's charts give 1.38.
///
/// For a factor F the soil gets c/F and atan(tan(phi)/F) (the apex stays), starts from the geostatic stress and the
/// gravity stage (docs/theory.md §20) steps until the unbalanced force ratio stays below 1e-4 for 10 steps, or gives
/// up at the step limit. The slope stands at F when the stage settles within the limit (Griffiths & Lane's
/// non-convergence criterion, with the dynamic relaxation of Dawson, Roth & Drescher 1999 for their iterations): the
/// factor of safety lies between the largest F that settles and the smallest that does not. The limit is a multiple
/// of the steps the slope takes at F = 1 (docs/verification-notes.md, "Slope stability by strength reduction", for
/// the measured steps and how the bracket depends on the multiple). Linear hats, 2 x 2 particles per cell, MUSL.

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "../libmpm/scene_fixture.hpp"
#include "mpm/simulation/gravity_stage.hpp"

namespace mpm::verification::strength_reduction {

inline constexpr double slope_phi = 20;        ///< deg
inline constexpr double slope_cohesion = 1e4;  ///< Pa: 0.05 gamma H

/// The scene at reduction factor F, cell size h (m), with the stage's step limit.
inline std::string slope_scene(double F, double h, long long max_steps) {
  const double t = std::tan(slope_phi * std::numbers::pi / 180);
  const double phi = std::atan(t / F) * 180 / std::numbers::pi, c = slope_cohesion / F, apex = slope_cohesion / t;
  char text[1400];
  std::snprintf(text, sizeof text, R"yaml(
dimension: 2
grid: {origin: [0, 0], extent: [36, 14], cell_size: %.17g, boundary: {x_min: slip, y_min: fixed}}
materials:
  soil: {model: mohr_coulomb, density: 2000, youngs_modulus: 1.0e8, poisson_ratio: 0.3, friction_angle: %.17g,
         cohesion: %.17g, tension_cutoff: %.17g}
bodies:
  - {name: slope, material: soil, shape: {type: polygon, vertices: [[0, 0], [32, 0], [12, 10], [0, 10]]}, volume: lattice}
sets: {all: {body: slope}}
conditions: [{set: all, initial_stress: geostatic}]
solver:
  shape_function: linear
  cfl: 0.5
  end_time: 1.0e-3
  gravity: [0, -10]
  gravity_stage: {tolerance: 1.0e-4, max_steps: %lld, on_no_equilibrium: warn}
)yaml",
                h, phi, c, apex, max_steps);
  return text;
}

/// The stage's report for the slope at F (the stage runs as the simulation is built).
inline GravityStageReport settle_slope(double F, double h, long long max_steps) {
  app::register_modules();
  GravityStageReport report;
  app::build_simulation<2>(parse_scene(slope_scene(F, h, max_steps), "slope.yaml"), true, &report);
  std::printf("[ measured ] slope, F = %.4g, h = %g m: %s\n", F, h, report.summary().c_str());
  return report;
}

}  // namespace mpm::verification::strength_reduction
