#pragma once
/// \file dam_break.hpp
/// The collapse of a water column on a rigid floor (review §5.4.1; validation against Martin & Moyce 1952,
/// Phil. Trans. R. Soc. A 244, Part IV): a column of width a and height n^2 a (n^2 = 2, a = 2.25 in =
/// 0.05715 m) at the left wall of a tank whose walls are all free-slip, released at t = 0 under gravity.
/// Weakly compressible water (newtonian_fluid: Tait EOS, gamma = 7) with the bulk modulus set from a Mach
/// number: c0 = U / Mach with U = 2 sqrt(g n^2 a) (the dam-break front speed of shallow-water theory),
/// K = rho0 c0^2 / gamma. The surge front Z = x_front / a against T = t sqrt(2 g / a); x_front = the largest
/// particle x plus half a particle spacing (so that Z = 1 at T = 0).

#include <string>
#include <vector>

namespace mpm::verification {

struct DamBreakSpec {
  double width = 0.05715;      ///< a, m
  double height_ratio = 2;     ///< n^2 = column height / a
  int cells_per_width = 16;    ///< a / h
  int particles_per_cell = 2;  ///< per axis
  double tank_length = 5;      ///< in units of a
  double tank_height = 3;      ///< in units of a
  std::string scheme = "musl";
  std::string shape_function = "linear";
  double mach = 0.05;         ///< U / c0 (0.1 lets the corner particles compress by up to 6%)
  double viscosity = 1.0e-3;  ///< mu of water, Pa s
  double end_T = 3.2;         ///< dimensionless end time
  double cfl = 0.5;
  double output_interval = 0;  ///< s, for the example's scene text (0: first and last frame)
  /// model incompressible_fluid (the pressure projection, docs/theory.md §21) instead of the Tait water: no bulk
  /// modulus, `mach` unused.
  bool incompressible = false;
};

struct DamBreakResult {
  std::vector<double> T, Z;          ///< front history, one entry per step (T = 0 first)
  double max_density_deviation = 0;  ///< max over particles and steps of |rho / rho0 - 1|
  bool inside_tank = true;           ///< every particle inside the tank at every step
  long long steps = 0, particles = 0;
  double wall_seconds = 0;
  std::string failure;  ///< empty, or the stability guard's message
  /// Z at dimensionless time T, linearly interpolated in the history.
  double front_at(double T) const;
};

std::string dam_break_scene(const DamBreakSpec& spec);
DamBreakResult run_dam_break(const DamBreakSpec& spec);

/// Martin & Moyce's measured (T, Z) for a column of width `width_inch` (2.25 or 1.125), read from
/// tests/data/dam_break_martin_moyce.csv; Z interpolated linearly at T.
struct MartinMoyce {
  std::vector<double> T, Z;
  double front_at(double T) const;
};
MartinMoyce martin_moyce(const std::string& csv_path, double width_inch = 2.25);

/// The largest |Z / Z_experiment - 1| over the experiment's points with T <= `last_T` (no shift of the clock).
double largest_front_deviation(const DamBreakResult& run, const MartinMoyce& experiment, double last_T = 3);

}  // namespace mpm::verification
