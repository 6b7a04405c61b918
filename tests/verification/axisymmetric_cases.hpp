#pragma once
/// \file axisymmetric_cases.hpp
/// Runners of the axisymmetric verification cases (docs/verification-notes.md), through scenes as a user
/// writes them (`grid.coordinates: axisymmetric`, x = r, y = z):
/// - radial vibration of a long elastic cylinder: R = 1 m, E = 100 Pa, nu = 0.3, rho = 1 kg/m^3, slip faces at
///   both ends of a slice 4 cells high (plane strain along z), free lateral surface; initial velocity the
///   fundamental radial mode v_r = A J1(kappa r). Its period is 2 pi / (kappa c_L), c_L^2 = (lambda + 2 mu)/rho, with
///   kappa R the first root of x J0(x) / J1(x) = (1 - 2 nu)/(1 - nu) (sigma_rr(R) = 0 for u_r = J1(kappa r); Graff,
///   Wave Motion in Elastic Solids, 1975, §8.2). Measured from the zero crossings of sum m_p v_rp.
/// - cooling of a long cylinder (thermal module): R = 1 m, rho = c = k = 1 (alpha = 1 m^2/s), T = T0 = 1 K at t = 0,
///   surface r = R held at 0 (the grid face x_max), ends insulated. The centre temperature against the series
///   T/T0 = sum_n 2 / (beta_n J1(beta_n)) J0(beta_n r / R) exp(-beta_n^2 alpha t / R^2), J0(beta_n) = 0
///   (Carslaw & Jaeger, Conduction of Heat in Solids, 1959, §7.4 eq. 4), at alpha t / R^2 = 0.2.

#include <string>
#include <vector>

#include "catalogue.hpp"

namespace mpm::verification {

struct AxisymmetricSpec {
  std::string scheme = "musl", shape_function = "linear";
  int cells = 16;  ///< cells across the radius
  int particles_per_cell = 2;
  double cfl = 0.5;  ///< vibration: on the CFL bound; cooling: on the diffusion bound
};

struct AxisymmetricResult {
  double value = 0;  ///< the measured period (s) or centre temperature (K)
  double exact = 0;  ///< its reference value
  double error = 0;  ///< |value - exact| / exact
  double h = 0;      ///< cell size, m
  double wall_seconds = 0;
  long long steps = 0, particles = 0;
  std::string failure;  ///< empty, or the stability guard's message
};

/// kappa R: the first root of x J0(x) / J1(x) = (1 - 2 nu) / (1 - nu).
double radial_mode_root(double nu);
/// The exact centre temperature ratio T(0, t) / T0 at tau = alpha t / R^2 (series of Carslaw & Jaeger).
double cylinder_cooling_centre(double tau);

AxisymmetricResult run_radial_vibration(const AxisymmetricSpec& spec);
AxisymmetricResult run_cylinder_cooling(const AxisymmetricSpec& spec);

/// The catalogue's families: `radial_vibration_axisym` (every scheme and axisymmetric shape function; error the
/// relative period error) and, with the thermal module, `cylinder_cooling_axisym` (MUSL; the relative error of
/// the centre temperature). Resolution = cells across the radius.
void add_axisymmetric_cases(std::vector<VerificationCase>& list, bool quick, int refinements);

}  // namespace mpm::verification
