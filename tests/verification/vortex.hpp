#pragma once
/// \file vortex.hpp
/// Generalized vortex (review §6.2.3, Brannon et al. 2011, Kamojjala et al. 2015; digest §C.8): the ring
/// R_i = 0.75 m <= R <= R_o = 1.25 m, each material circle turned rigidly by
///   alpha(t, R) = g(t) h(R),  h = 1 - 8 s^2 + 16 s^4,  s = (R - Rbar) / (R_i - R_o),  g = G sin(pi t / T0),
/// x = Q(alpha) X (eqs 6.13-6.16, with docs/errata.md #21: R_o for "R_0"; [0, T0] is half a sine period),
/// G = 1 rad, T0 = 1 s, end time 1 s. Neo-Hookean, E = 1e3 Pa, nu = 0.3 (as in the review; the motion is
/// isochoric, J = 1, so lambda does not enter the body force), rho0 = 1000 kg/m^3, 2D plane strain.
///
/// Deviations from the printed text, both needed for the manufactured solution to be one:
/// - Body force (eqs 6.17-6.18): b = a - Div P / rho0 gives, in the reference polar basis,
///     b_R =  [mu/rho0 (3 g h' + R g h'') - R g'' h] sin(alpha) + [mu/rho0 R (g h')^2 - R (g' h)^2] cos(alpha)
///     b_T = -[mu/rho0 (3 g h' + R g h'') - R g'' h] cos(alpha) + [mu/rho0 R (g h')^2 - R (g' h)^2] sin(alpha)
///   The printed b_Theta has "+ R (g' h)^2" (the centripetal acceleration -R (g'h)^2 e_r with the wrong sign
///   in its Theta component); checked against a finite-difference Div P. `printed_body_force` uses it.
/// - Initial velocity: the exact field v(X, 0) = g'(0) h(R) (-Y, X) with g'(0) = G pi / T0, not the
///   printed "identically zero" (with g = G sin(pi t/T0) the ring starts moving at up to 3.17 m/s).
///   `exact_initial_velocity = false` starts at rest as printed.
///
/// Particles fill a disk of radius R_o on the grid's sub-cells; those with R < R_i are removed before the
/// first step (the scene format has no annulus; the simulation is rebuilt from the filtered particles so
/// that the TLMPM caches and the guard's snapshot see the ring). The body force b(X_p, t) is set on the
/// particles before every step, at the reference position and the time at the start of the step. As in
/// the review, the velocity of every node outside the ring (|x_I| <= R_i or >= R_o, where the exact
/// velocity is zero) is set to zero at each grid-velocity stage. Errors: e1 and e2 of eqs A.11-A.13 with
/// u^ex(X, t) = (Q(alpha) - I) X, evaluated after every step.

#include <array>
#include <string>

namespace mpm {

struct VortexSpec {
  std::string scheme;          ///< usl, musl, usf, tlmpm
  std::string shape_function;  ///< linear, cubic_bspline, quadratic_bspline, bernstein, gimp, cpgimp
  int cells_across;            ///< cells per side of the grid square [-1.5, 1.5]^2 m (even for bernstein)
  int particles_per_cell_per_axis;
  double flip_fraction;  ///< 1 = FLIP, 0 = PIC (the review: 0.99)
  double amplitude = 1;  ///< G, rad (the review: 1)
  /// dt = courant h / (c + v_max) with c the dilatational wave speed (1.16 m/s) and v_max the largest
  /// exact speed (3.17 m/s for G = 1), rounded down so that a whole number of steps ends at end_time.
  double courant = 0.2;
  bool fix_nodes_outside_ring = true;  ///< the review's nodal condition (see above)
  bool exact_initial_velocity = true;  ///< false: start at rest, as printed in the review
  bool printed_body_force = false;     ///< true: eq. 6.18 as printed (wrong sign, see above)
  double end_time = 1;                 ///< s
  std::string output_directory;        ///< non-empty: write ParaView frames of the ring there
  double output_interval = 0.05;       ///< s, with output_directory
};

struct VortexResult {
  double e1 = 0;            ///< max over steps of e(t^n) (eq. A.11-A.12), m
  double e2 = 0;            ///< normalised space-time error (eq. A.13), -
  double wall_seconds = 0;  ///< building the scene and running it
  long long steps = 0;
  long long particles = 0;  ///< in the ring (after the removal)
  double h = 0;             ///< cell size, m (the Bernstein element is 2h)
  double dt = 0;            ///< s
  std::string failure;      ///< empty, or the stability-guard message (then e1 = e2 = +inf)
};

/// The scene the runner builds, as YAML text: a disk of radius R_o with the exact initial velocity (the
/// runner then removes the particles of the hole). `mpm run` accepts it (without body force and hole).
std::string vortex_scene_yaml(const VortexSpec& spec);

/// The exact displacement u(X, t) = (Q(alpha) - I) X (zero outside the ring), m.
std::array<double, 2> vortex_displacement(const std::array<double, 2>& X, double t, double amplitude = 1);
/// The body force the runner applies at reference position X and time t (m/s^2): b = a - Div P / rho0,
/// or eq. 6.18 as printed when `printed`. Zero outside the ring.
std::array<double, 2> vortex_body_force(const std::array<double, 2>& X, double t, bool printed = false,
                                        double amplitude = 1);

/// Runs one case and returns its error norms. Throws std::invalid_argument for a bad spec (and SceneError
/// if the scene is rejected); a run stopped by the stability guard returns e1 = e2 = +inf and `failure`.
VortexResult run_vortex(const VortexSpec& spec);

}  // namespace mpm
