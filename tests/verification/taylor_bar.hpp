#pragma once
/// \file taylor_bar.hpp
/// The Taylor bar of Love & Sulsky (reference 003 §4.1) with the explicit schemes, axisymmetric: a
/// copper bar, R0 = 3.2 mm, L0 = 32.4 mm, hits a rigid frictionless wall at 227 m/s; J2 plasticity with linear
/// hardening, E = 116.9 GPa, nu = 0.35, sigma_Y = 0.4 GPa, H = 0.1 GPa, rho = 8930 kg/m^3; 80 us. Reference: the
/// converged finite-element results for this bar, final length L_f = 21.42-21.48 mm and impact-face radius
/// R_f = 7.12-7.22 mm (Simo 1992; Zienkiewicz et al. 1998), quoted by the issue; the implicit scheme
/// will be compared with the same numbers.
///
/// The grid: r in [0, 8.8 mm] (the foot spreads to about 7.2 mm), z in [0, L0 + one cell], square cells of size h;
/// the wall is a slip condition on the face z = 0. Models: `hencky_j2` (finite-strain J2 on b^e, the
/// formulation of the FE references) or `j2_plasticity` (hypoelastic Jaumann J2 with a linear EOS). The shape is
/// measured from the particle centres with the offsets of taylor_anvil.hpp (L0 and R0 at t = 0): L_f the axial
/// extent, R_f the largest radius (at the impact face).

#include <string>

namespace mpm {

struct TaylorBarSpec {
  std::string scheme = "musl", shape_function = "linear";
  std::string model = "hencky_j2";  ///< or j2_plasticity
  double h = 0.4e-3;                ///< m; 0.4 mm: 8 cells across the radius (the radial cell size)
  double h_z = 0;                   ///< m, the axial cell size; 0: h (square cells)
  /// The paper's box [0, 7.2] x [0, 32.4] mm (9 x 50 cells of 0.8 x 0.648 mm at h = 0.8e-3, h_z = 0.648e-3);
  /// otherwise r in [0, 8.8 mm] and one free cell above the bar.
  bool paper_box = false;
  int particles_per_cell = 2;  ///< per axis
  double cfl = 0.5;            ///< the explicit schemes
  double dt = 1e-6;            ///< s, scheme implicit (a fixed step)
  int max_newton_iterations = 50;
  double end_time = 80e-6;       ///< s
  std::string output_directory;  ///< non-empty: frames every 10 us there (ParaView)
};

struct TaylorBarResult {
  double length = 0, radius = 0;     ///< L_f, R_f, m
  double energy_error = 0;           ///< |E(end) - E0| / E0, E = kinetic + stored + plastic work
  double largest_rise = 0;           ///< largest step-to-step rise of E (kinetic + stored), / E0
  double kinetic_fraction = 0;       ///< kinetic energy at the end / initial
  double plastic_work_fraction = 0;  ///< plastic work at the end / E0
  double face_plastic_strain = 0;    ///< equivalent plastic strain of the impact-face particle nearest the axis
  double largest_plastic_strain = 0;
  double wall_seconds = 0;
  double cpu_seconds = 0;     ///< process CPU time of the run (std::clock; less the runner's per-step energy audit)
  double simulated_time = 0;  ///< s, reached
  long long steps = 0, particles = 0;
  /// Scheme implicit (solver.csv summed over the steps): Newton and GMRES iterations, residual evaluations,
  /// the largest Newton count of a step, and the wall time in the projection, in R and in the LU.
  long long newton = 0, gmres = 0, residuals = 0;
  int max_newton = 0;
  double projection_seconds = 0, residual_seconds = 0, factorization_seconds = 0;
  std::string failure;
};

/// The scene text (also examples/17_love_sulsky_bar/*.yaml).
std::string taylor_bar_scene(const TaylorBarSpec& spec);
TaylorBarResult run_taylor_bar(const TaylorBarSpec& spec);

}  // namespace mpm
