#pragma once
/// \file hertz_sphere.hpp
/// An elastic sphere dropped on a rigid plane, axisymmetric (contact module): a sphere R = 0.1 m (a disk
/// centred on the axis of an axisymmetric grid; rho = 1000 kg/m^3, E = 10 MPa, nu = 0.3) falls at v0 = 1 m/s onto a
/// contact plane at z = 0, a quarter cell below it at the start. Hertz's quasi-static impact (Johnson, Contact
/// Mechanics, 1985, §11.4), E* = E / (1 - nu^2) for a rigid plane, m the sphere's mass:
///   duration t_c = 2.87 (m^2 / (R E*^2 v0))^(1/5) = 12.3 ms,
///   indentation delta_max = (15 m v0^2 / (16 E* R^(1/2)))^(2/5) = 4.18 mm,
///   peak force F_max = 4/3 E* R^(1/2) delta_max^(3/2) = 1252 N (the whole sphere: forces are per revolution).
/// The contact force is the module's (the impulse of its velocity corrections per step), averaged over windows of
/// `window` seconds: per step it jumps by about 15% as particles cross cells; the peak of the averaged force and
/// the time during which it exceeds 2% of that peak are compared with Hertz.

#include <string>

namespace mpm::verification {

struct HertzSpec {
  std::string scheme = "musl", shape_function = "linear", onset = "grid";
  int cells_per_radius = 40;
  int particles_per_cell = 2;
  double window = 0.25e-3;  ///< s, about t_c / 50
};

struct HertzResult {
  double peak = 0, duration = 0;              ///< of the window-averaged contact force: N, s
  double exact_peak = 0, exact_duration = 0;  ///< Hertz
  double impulse = 0;                         ///< N s, integral of the contact force
  double momentum_change = 0;                 ///< N s, the sphere's axial momentum after minus before
  double rebound = 0;                         ///< m/s, the sphere's axial velocity at the end (elastic: v0)
  double wall_seconds = 0;
  long long steps = 0, particles = 0;
  std::string failure;
};

HertzResult run_hertz_sphere(const HertzSpec& spec);

}  // namespace mpm::verification
