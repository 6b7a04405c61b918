#pragma once
/// \file heat_conduction.hpp
/// Runners of the thermal verification tests of review §5.3.3 (digest C.5), through a scene as a user
/// writes it (thermal module): the 1D bar of eq. 5.27 (rho = c = k = 1, L = 1, T = 0 at t = 0, x = 0 held at
/// T0 = 0 and x = 1 raised to T1 = 1) and the 2D plate of eq. 5.28 (unit square, T = 0 at t = 0, boundary
/// raised to T1 = 100). The temperature is held on the grid nodes of the faces (Alg. 8), or, for the plate,
/// optionally on the particles of the boundary cells as in the paper. The time step is cfl x the diffusion
/// bound h^2 rho c / (2 dim k) (the paper's 1D step 8e-5 is above that bound: docs/errata.md #13).

#include <string>

namespace mpm::verification {

struct HeatSpec {
  int dimension = 1;
  int cells = 100;             ///< per side
  int particles_per_cell = 1;  ///< per axis
  std::string scheme = "musl", shape_function = "linear";
  double cfl = 0.8;                ///< factor on the diffusion bound
  double end_time = 0.05;          ///< s
  bool particle_boundary = false;  ///< 2D: hold the particles of the boundary cells instead of the face nodes
  /// 1D, TLMPM: the bar stretches freely with v = a x (1/s; stress-free, E = 1e-9), F = 1 + a t. In the reference
  /// coordinates the capacity per length stays rho c and the conductance becomes k/F, so T(X, t) is eq. 5.27 at
  /// the time tau = ln(1 + a t)/a (the exact value the errors are taken against).
  double stretch_rate = 0;
};

struct HeatResult {
  double max_error = 0;  ///< max over grid nodes |T_I - T_exact| / (T1 - T0) at end_time (-)
  /// The same for the grid field at the nodes, T_h(x_I) = sum_J phi_J(x_I) T_J: the nodal values T_I are the
  /// coefficients of the field, equal to it only where phi_J(x_I) = delta_IJ (linear, Lagrange, GIMP and CPDI,
  /// whose grid basis is the hat; not the B-splines and Bernstein's mid nodes).
  double max_field_error = 0;
  double probe = 0;           ///< grid temperature at x = 0.5 (1D) or the centre (2D), K
  double probe_exact = 0;     ///< exact value there, K
  double thermal_energy = 0;  ///< sum m c (T - T_ref) at the end, J
  double h = 0, dt = 0, wall_seconds = 0;
  long long steps = 0, particles = 0;
  std::string failure;
};

/// Exact solutions: eq. 5.27 (T0 = 0, T1 = 1, L = 1) and eq. 5.28 (T0 = 0, T1 = 100, unit square).
double heat_bar_exact(double x, double t);
double heat_plate_exact(double x, double y, double t);

HeatResult run_heat(const HeatSpec& spec);

}  // namespace mpm::verification
