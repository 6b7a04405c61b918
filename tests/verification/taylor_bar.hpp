#pragma once
/// \file taylor_bar.hpp
/// The Taylor bar of Love & Sulsky (reference 003 §4.1) with the explicit schemes, axisymmetric (issue 16): a
/// copper bar, R0 = 3.2 mm, L0 = 32.4 mm, hits a rigid frictionless wall at 227 m/s; J2 plasticity with linear
/// hardening, E = 116.9 GPa, nu = 0.35, sigma_Y = 0.4 GPa, H = 0.1 GPa, rho = 8930 kg/m^3; 80 us. Reference: the
/// converged finite-element results for this bar, final length L_f = 21.42-21.48 mm and impact-face radius
/// R_f = 7.12-7.22 mm (Simo 1992; Zienkiewicz et al. 1998), quoted by the issue; the implicit scheme (issue 17)
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
  double h = 0.4e-3;                ///< m; 0.4 mm: 8 cells across the radius
  int particles_per_cell = 2;       ///< per axis
  double cfl = 0.5;
  double end_time = 80e-6;       ///< s
  std::string output_directory;  ///< non-empty: frames every 10 us there (ParaView)
};

struct TaylorBarResult {
  double length = 0, radius = 0;  ///< L_f, R_f, m
  double energy_error = 0;        ///< |E(end) - E0| / E0, E = kinetic + stored + plastic work
  double kinetic_fraction = 0;    ///< kinetic energy at the end / initial
  double wall_seconds = 0;
  long long steps = 0, particles = 0;
  std::string failure;
};

/// The scene text (also examples/17_love_sulsky_bar/*.yaml).
std::string taylor_bar_scene(const TaylorBarSpec& spec);
TaylorBarResult run_taylor_bar(const TaylorBarSpec& spec);

}  // namespace mpm
