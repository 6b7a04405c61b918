#pragma once
/// \file mms.hpp
/// Method of manufactured solutions on the axis-aligned unit segment, square and cube (review §6.2.1-6.2.2,
/// App. A; digest §C.6-C.7):
///   u_i(X, t) = G sin(pi X_i) sin(c pi t + phi_i),  phi = [0, pi, pi],  c = sqrt(E / rho0),
/// Neo-Hookean with E = 1e7 Pa, nu = 0.3, rho0 = 1000 kg/m^3 (1D uniaxial strain, 2D plane strain),
/// T = 2/c (one period), dt = 0.2 h / c (or adaptive, MmsSpec::cfl), only the normal velocity component fixed on each
/// face. The body force of eq. A.8 / 6.9 is set on the particles before every step (at X_p and the time at the start of
/// the step). Errors are the e1 and e2 norms of eqs A.11-A.13, evaluated after every step.

#include <string>

namespace mpm {

struct MmsSpec {
  int dimension;               ///< 1, 2 or 3
  std::string scheme;          ///< usl, musl, usf, tlmpm
  std::string shape_function;  ///< linear, cubic_bspline, quadratic_bspline, bernstein, gimp, cpgimp
  int cells_per_side;          ///< cells per axis of the unit box (even for bernstein)
  int particles_per_cell_per_axis;
  double G;              ///< amplitude of the displacement, m
  double flip_fraction;  ///< 1 = FLIP, 0 = PIC
  double end_time_periods = 1;
  /// 0: fixed dt = 0.2 h / c (c of the undeformed material); > 0: adaptive dt = cfl x the CFL bound of the
  /// current state (needed when the deformation stiffens the material: at det F = 0.05 Neo-Hookean waves are
  /// several times faster).
  double cfl = 0;
  std::string output_directory{};  ///< when not empty: ParaView frames and energy.csv written there (OutputWriter)
  int output_frames = 20;          ///< frames per period when writing
};

struct MmsResult {
  double e1 = 0;            ///< max over steps of e(t^n) (eq. A.11-A.12), m
  double e2 = 0;            ///< normalised space-time error (eq. A.13), -
  double wall_seconds = 0;  ///< building the scene and running it
  long long steps = 0;
  long long particles = 0;
  double min_J = 1;     ///< smallest det F over the particles and steps
  double h = 0;         ///< cell size, m (the Bernstein element is 2h)
  std::string failure;  ///< empty, or the stability-guard message (then e1 = e2 = +inf)
};

/// The scene of the manufactured solution, as YAML text (for inspection: `mpm run` accepts it, without the
/// body force).
std::string mms_scene_yaml(const MmsSpec& spec);

/// Runs one case and returns its error norms. Throws std::invalid_argument for a bad spec (and SceneError
/// if the scene is rejected); a run stopped by the stability guard returns e1 = e2 = +inf and `failure`.
MmsResult run_mms(const MmsSpec& spec);

}  // namespace mpm
