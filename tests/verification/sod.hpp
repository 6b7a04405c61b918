#pragma once
/// \file sod.hpp
/// Sod's shock tube (review §6.1.4; digest C.4) as a runnable case: 1D tube [0, 1] with fixed ends, the
/// diaphragm at 0.5, left rho = 1, p = 1, right rho = 0.125, p = 0.1, ideal gas gamma = 1.4, compared with
/// the exact Riemann solution (sod_exact.hpp) at end_time. Errors are L1 over the tube, divided by the
/// jump of each quantity across the problem (density 0.875, velocity u* = 0.92745, pressure 0.9):
///   on the particles:  sum_p V_p |q_p - q(x_p)|;
///   on the grid:       sum_I h |q_I - q(x_I)| over the nodes that carry mass, where the nodal values are
///                      the review's grid data (Fig. 68): rho_I = m_I / h, velocity and pressure mapped
///                      mass-weighted with hat functions (a post-processing of the particles, the same for
///                      every shape function of the run).

#include <string>

namespace mpm::verification {

struct SodSpec {
  int cells = 200;
  int particles_per_cell = 3;
  std::string scheme = "musl";
  std::string shape_function = "linear";
  double flip_fraction = 1;
  double viscosity_linear = 0;     ///< c_1 of eq. 5.35
  double viscosity_quadratic = 0;  ///< c_2
  double cfl = 0.2;
  double end_time = 0.143;
};

struct SodErrors {
  double density = 0, velocity = 0, pressure = 0;
};

struct SodResult {
  SodErrors particles, grid;
  double energy_change = 0;  ///< (E_end - E_0) / E_0, kinetic + internal
  double volume_sum = 0;     ///< sum of the particle volumes (the tube is 1 long: the volume drift)
  long long steps = 0;
  long long particle_count = 0;
  double wall_seconds = 0;
  std::string failure;  ///< empty, or the stability guard's message
};

/// The scene text of the case (also used by examples/13_sod).
std::string sod_scene(const SodSpec& spec);
SodResult run_sod(const SodSpec& spec);

}  // namespace mpm::verification
