#pragma once
/// \file taylor_anvil.hpp
/// Taylor anvil (review §6.3.1, Table 5; digest §C.9): an OFHC copper cylinder, L0 = 25.4 mm, D0 = 7.6 mm,
/// hits a rigid frictionless wall at 190 m/s. Johnson-Cook flow (A = 65 MPa, B = 356 MPa, n = 0.37,
/// C = 0.013, rate0 = 1/s), Mie-Gruneisen EOS (c0 = 3933 m/s, S = 1.5, Gamma0 = 0), E = 115 GPa,
/// nu = 0.31, rho0 = 8940 kg/m^3; no damage, no thermal softening (as in the review). 3D, cylinder axis z,
/// wall z = 0 as a slip condition on the grid face z_min (v_z = 0 on its nodes, the review's "zeroing v_x
/// of the bottom nodes"). The cylinder's base lies on the wall; it starts moving at -190 m/s.
///
/// Grids (cell size h):
///   tlmpm: just encloses the cylinder, x, y in [-4, 4] mm, z in [0, ceil(L0/h) h] (25.5 mm and the review's
///          74,052 particles at h = 0.25 mm, 1 particle per cell);
///   usl/musl: covers the deformed shape, x, y in [-8, 8] mm, z up to one more cell (8 particles per cell).
///   axisymmetric: the same extents in r (from the axis) and z, particles per cell per axis as in 3D.
///
/// The run stops when the kinetic energy falls below 1% of its initial value, or when the axial momentum
/// reaches zero (the rod has stopped; with UL-MPM the elastic ringing that remains keeps about 1.2% of the
/// kinetic energy at h = 1 mm, measured), or at 80 us, checked every 5 steps; the final
/// shape is measured from the particle centres, each measure offset by the gap between the initial centres
/// and the initial surface so that it gives L0 and D0 at t = 0:
///   L_f: axial extent of the particles;  D_f: largest diameter (at the impact face);
///   W_f: bulge, the largest diameter of the particles whose axial position lies within h/2 of 0.2 L0 from
///        the wall (Johnson & Holmquist 1988 measure W there; the review leaves it to the eye in Ovito).
/// Error (eq. 6.19): Delta = 1/3 (|L_f - 16.2|/16.2 + |D_f - 13.5|/13.5 + |W_f - 10.1|/10.1), the
/// experiment of Johnson & Holmquist 1988 (mm).

#include <string>

namespace mpm {

struct TaylorSpec {
  std::string scheme = "tlmpm";           ///< tlmpm, musl, usl
  std::string shape_function = "linear";  ///< linear, cubic_bspline
  double h = 0.5e-3;                      ///< cell size, m (8 mm / h must be a whole number)
  int particles_per_cell = 0;             ///< per axis; 0 = 1 for tlmpm, 2 otherwise
  double cfl = 0.5;
  double strain_rate_coefficient = 0.013;  ///< Johnson-Cook C (Table 5; Karamelo's input uses 0)
  double max_time = 80e-6;                 ///< s, the run stops here at the latest (the scene's end_time)
  std::string output_directory;            ///< non-empty: write the final state there (ParaView)
  /// The same rod as a 2D axisymmetric run (`grid.coordinates: axisymmetric`, x = r in [0, 4 or 8 mm], y = z):
  /// the box r <= R0, 0 <= z <= L0 of the same cell size and particles per cell.
  bool axisymmetric = false;
};

struct TaylorResult {
  double length = 0, diameter = 0, bulge = 0;  ///< L_f, D_f, W_f, m
  double error = 0;                            ///< Delta of eq. 6.19
  double time = 0;                             ///< s, when the run stopped (see above)
  double kinetic_fraction = 0;                 ///< kinetic energy then / initial
  double energy_error = 0;                     ///< |E_total(end) - E_0| / E_0 (E includes the plastic work)
  double max_plastic_strain = 0;
  double wall_seconds = 0;  ///< stepping only (building the scene excluded)
  double cpu_seconds = 0;   ///< the process's CPU time over the same span (all threads; robust to a loaded machine)
  long long steps = 0;
  long long particles = 0;
  double particle_updates_per_second = 0;
  std::string failure;  ///< empty, or the stability-guard message
};

/// Builds the scene (YAML text through parse_scene and build_simulation, as a user scene), runs it and
/// measures the final shape.
TaylorResult run_taylor_anvil(const TaylorSpec& spec);

/// The scene text run_taylor_anvil uses (also written as examples/05_taylor_anvil/*.yaml).
std::string taylor_anvil_scene(const TaylorSpec& spec);

}  // namespace mpm
