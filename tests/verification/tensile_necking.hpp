#pragma once
/// \file tensile_necking.hpp
/// Tensile test to failure (review §6.3.2, Tables 7-8 as corrected in docs/errata.md #23-24): a smooth
/// Weldox 460E cylinder, 30 mm long, 6 mm in diameter, TLMPM with one particle per cell, axis z. The grid
/// just encloses it; the nodes of its end faces z = 0 and z = 30 mm move at -/+ v(t) along the axis,
/// v = v_max (1 - exp(-t / tau)) (the review: v_max = 1 mm/ms, tau = 1 ms), and are held laterally (grips).
/// Johnson-Cook: A = 499 MPa, B = 382 MPa, n = 0.458, C = 0; damage D1 = 0.636, D2 = 1.936, D3 = -2.969,
/// D4 = 0 (quasi-static, as Karamelo's input; Table 8 gives -0.0140); Mie-Gruneisen c0 = 5166 m/s (docs/errata.md
/// #23), S = 1.5, Gamma0 = 0; rho0 = 7750 kg/m^3, E = 211 GPa, nu = 0.33.
///
/// Measured every `record_interval` steps:
///   engineering strain  e = 2 u(t) / L0, u(t) = v_max (t - tau (1 - exp(-t / tau))) the grip displacement;
///   engineering stress  s = force / A0 = (sum_p P_zZ V0_p) / (sum_p V0_p): in equilibrium every reference
///                       cross-section carries the same force, so the volume average of the nominal stress
///                       P = J sigma F^-T over the whole specimen is the force per initial area (A0 = the
///                       particles' cross-section).
/// At the end: the neck (the reference slice of particles with the smallest current radius, the 2 slices at
/// each grip excluded), and the damage there. The run stops when the stress has fallen below 10% of its
/// peak after the peak (fracture), or at `max_strain`.

#include <string>
#include <vector>

namespace mpm {

struct TensileSpec {
  std::string shape_function = "linear";  ///< linear, cubic_bspline, bernstein
  double h = 0.5e-3;                      ///< cell size, m (6 mm / h and 30 mm / h whole numbers)
  double v_max = 1.0;                     ///< m/s
  double tau = 1e-3;                      ///< s
  double max_strain = 0.5;                ///< engineering strain at which the run stops at the latest
  int record_interval = 50;               ///< steps between records
  double cfl = 0.5;
};

struct TensileResult {
  std::vector<double> strain, stress;  ///< engineering strain (-) and stress (Pa)
  double peak_stress = 0;              ///< Pa
  double strain_at_peak = 0;
  double neck_z = 0;           ///< reference axial position of the neck, m
  double neck_radius = 0;      ///< current radius there (largest particle distance to the axis), m
  double neck_max_damage = 0;  ///< the largest damage in the neck slice
  double max_damage_z = 0;     ///< reference z of the first particle with the largest damage, m
  double failure_strain = 0;   ///< engineering strain when the stress fell below 10% of the peak (0: never)
  long long steps = 0, particles = 0;
  double wall_seconds = 0;
  std::string failure;  ///< stability guard message, if any
};

std::string tensile_necking_scene(const TensileSpec& spec);
TensileResult run_tensile_necking(const TensileSpec& spec);

}  // namespace mpm
