#pragma once
/// \file tlmpm_paper.hpp
/// The three verification cases of the 1D total-Lagrangian MPM report of Nuttall (2025, "the 000 paper",
/// §IV), run with our TLMPM (scheme tlmpm, MUSL double mapping, flip_fraction = the paper's Newmark alpha
/// = 0.5) on a Neo-Hookean bar in uniaxial strain (dimension 1), fixed at X = 0:
///   A  quasi-static column compression (eq. 69): L = 0.1 m, E = 5e3 Pa, nu = 0.3, rho = 10 kg/m^3,
///      gravity -9.81 m/s^2, end traction ramped to tau0 = -1e4 Pa by t = 1 and held to t = 1.2, against
///      the EXACT static solution of the Neo-Hookean bar (column_exact);
///   B  dynamic step loading (eq. 71, converted to SI): E = 250 MPa, nu = 0, rho = 1935.5 kg/m^3,
///      L = 5 mm, tau = -1.27 MPa from t = 0, T = 0.2 ms, against the series of eq. 70 (step_load_series);
///   C  energy (eq. 72): the case-A bar without loads, every particle given the same speed
///      v0 = sqrt(2 E0 / M) (E0 = 0.05 mJ on A = 1e-4 m^2), the total energy must never exceed E0.
/// In 1D the engine works per unit cross-section: masses in kg/m^2, energies in J/m^2.
///
/// Resolution is given in ELEMENTS as in the paper: for the two-cell families (lagrange_quadratic,
/// bernstein) an element is two grid cells, otherwise one. Particles sit at the sub-cell centres of the
/// filler: `particles_per_element` evenly spaced points per element (the paper's layout, §II E, which are
/// not Gauss points); it must be a multiple of the cells per element. The time step is
/// dt = dt_factor * (element length) / c with c = sqrt(E / rho) (eq. 2), as in the paper's tables.

#include <string>
#include <vector>

namespace mpm {

// ---- Case A: quasi-static column compression -------------------------------------------------------

struct ColumnSpec {
  std::string shape_function = "lagrange_quadratic";
  int elements = 10;
  int particles_per_element = 2;
  /// "linear": the paper's Ramp(tau0, t, T_ramp) = tau0 min(t / T_ramp, 1), whose rate jumps at t = 0 and
  /// at T_ramp; "smooth": tau0 (s - sin(2 pi s) / (2 pi)), s = min(t / T_ramp, 1), whose rate and
  /// acceleration vanish at both ends.
  std::string ramp = "linear";
  double ramp_time = 1.0;  ///< s (the paper's pseudo-time)
  double end_time = 1.2;   ///< s
  double dt_factor = 0.1;  ///< dt = dt_factor * element length / c
  double flip_fraction = 0.5;
  double gravity = -9.81;  ///< m/s^2
  /// false (the paper): gravity in full from t = 0, a step load that leaves the bar vibrating with an
  /// amplitude of a few 1e-5 m (the static sag of the still soft bar), which the undamped MUSL keeps;
  /// true: gravity ramped with the traction's profile, applied as the particle field "body_force".
  bool ramp_gravity = false;
  int history_interval = 0;  ///< > 0: record the end node's displacement every this many steps
};

struct ColumnExact {
  double u = 0;  ///< displacement, m
  double F = 1;  ///< stretch F11
  double P = 0;  ///< first Piola-Kirchhoff stress P11 (= Cauchy sigma11 in 1D uniaxial strain), Pa
};
/// Exact static solution at X in [0, L]: P(X) = tau0 + rho0 g (L - X) (dP/dX + rho0 g = 0, P(L) = tau0),
/// F(X) = P^-1(P(X)) with P(F) = lambda ln F / F + mu (F - 1/F) (monotonic: safeguarded Newton),
/// u(X) = int_0^X (F - 1) dX' (Gauss-Legendre, exact to rounding).
ColumnExact column_exact(double X, double gravity = -9.81);

/// Errors at the end time. Two displacements are measured: the grid's, D_I = sum over the steps of
/// dt v_I^{n+1} (the re-mapped nodal velocities the TLMPM integrates F with, so F_p = 1 + sum_I D_I
/// grad phi_I(X_p) exactly), compared at the element vertices (where every family interpolates); and the
/// particles' own positions x_p, which the TLMPM moves with the first-mapped velocities v~_I.
struct ColumnResult {
  double tip_exact = 0;           ///< u(L) of the static solution, m
  double tip = 0;                 ///< D of the node at X = L, m
  double tip_particle = 0;        ///< u_p + (F_p - 1)(L - X_p) of the end particle, m
  double max_nodal_error = 0;     ///< max over the vertices of |D_I - u(X_I)| / |u(L)|, -
  double max_particle_error = 0;  ///< max_p |x_p - X_p - u(X_p)| / |u(L)|, -
  double max_stress_error = 0;    ///< max_p |sigma_p - P(X_p)| / |tau0|, -
  double wall_seconds = 0;
  long long steps = 0;
  long long particles = 0;
  std::vector<double> time, tip_history;  ///< with history_interval: t and D of the end node
  std::string failure;                    ///< empty, or the stability-guard message
};
std::string column_scene_yaml(const ColumnSpec& spec);
/// Runs case A. `scene_yaml`, when given, replaces the generated scene (it must describe the same bar,
/// fixed at X = 0 on a grid [0, L]; the spec then gives the exact solution and the element size).
ColumnResult run_column(const ColumnSpec& spec, const std::string& scene_yaml = "");

// ---- Case B: dynamic step loading ----------------------------------------------------------------

struct StepLoadSpec {
  std::string shape_function = "lagrange_quadratic";
  int elements = 32;
  int particles_per_element = 2;
  double end_time = 2e-4;  ///< s
  double dt_factor = 0.1;
  double flip_fraction = 0.5;
  int series_terms = 4000;  ///< terms of eq. 70
  /// Pa: the paper's -1.27 MPa (a 0.5 % strain, where the Neo-Hookean bar already differs from the
  /// linear series by about 1 % of the amplitude); a smaller load isolates the discretisation error.
  double traction = -1.27e6;
};

/// Eq. 70 (small-strain series, Meirovitch eq. 8.71): u(X, t) = 8 tau L / (pi^2 E) sum_{n=1}^{terms}
/// (-1)^{n-1} / (2n-1)^2 sin((2n-1) pi X / 2L) (1 - cos((2n-1) pi c t / 2L)), c = sqrt(E / rho).
double step_load_series(double X, double t, int terms, double traction = -1.27e6);
/// The same series summed in closed form at the tip X = L (d'Alembert): a triangle wave of period 4L/c
/// rising with slope tau c / E to 2 tau L / E at t = 2L/c.
double step_load_tip_closed_form(double t, double traction = -1.27e6);

struct StepLoadResult {
  double rms_error = 0;     ///< RMS over the steps of u_p(t) - u(X_p, t) for the end particle, m
  double rms_relative = 0;  ///< rms_error / (2 |tau| L / E), -
  double max_relative = 0;  ///< max over the steps of |u_p - u| / (2 |tau| L / E), -
  double amplitude = 0;     ///< 2 |tau| L / E, m
  /// The same RMS for the grid displacement of the end node (X = L), D = sum dt v^{n+1}, against eq. 70
  /// at X = L, over 2 |tau| L / E.
  double rms_relative_node = 0;
  double X_end = 0;                          ///< reference position of the end particle, m
  double element_length = 0;                 ///< m
  std::vector<double> time, tip, tip_exact;  ///< the history (time, end-particle displacement, eq. 70)
  double wall_seconds = 0;
  long long steps = 0;
  std::string failure;
};
std::string step_load_scene_yaml(const StepLoadSpec& spec);
StepLoadResult run_step_load(const StepLoadSpec& spec);

// ---- Case C: energy -------------------------------------------------------------------------------

struct EnergySpec {
  std::string shape_function = "lagrange_quadratic";
  int elements = 32;
  int particles_per_element = 4;  ///< the paper uses 3; the filler needs a multiple of 2 for two-cell elements
  double end_time = 0.2;          ///< s (the paper's text; its table says 0.05)
  double dt_factor = 0.2;
  double flip_fraction = 0.5;
  double initial_energy = 5e-5;  ///< J on the cross-section A = 1e-4 m^2 (0.05 mJ)
  bool fixed_end = true;         ///< the paper keeps u(0) = 0
};
struct EnergyResult {
  double E0 = 0;           ///< J/m^2: kinetic + strain energy before the first step
  double max_total = 0;    ///< J/m^2: max over the steps of kinetic + strain
  double min_total = 0;    ///< J/m^2
  double final_total = 0;  ///< J/m^2
  double max_growth = 0;   ///< max over the steps of (E - E0) / E0 (<= 0 when the energy never grows)
  double wall_seconds = 0;
  long long steps = 0;
  std::string failure;
};
std::string energy_scene_yaml(const EnergySpec& spec);
EnergyResult run_energy(const EnergySpec& spec);

}  // namespace mpm
