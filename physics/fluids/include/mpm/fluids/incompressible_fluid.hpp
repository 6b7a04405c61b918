#pragma once
/// \file incompressible_fluid.hpp
/// Incompressible Newtonian fluid (`model: incompressible_fluid`, docs/theory.md §21): the stress is
///   sigma = 2 mu dev(D) - p I,
/// where the law gives the viscous part only and the pressure p is the Lagrange multiplier of div v = 0, found each
/// step by the grid projection (pressure_projection.hpp, eqs 21.1-21.4), which adds -p I to the stress at the end of
/// the step (for the output) and takes it out again before the next transfer. No sound speed: the time step follows
/// the flow (h / |v|) and the projection's free-fall bound, not an artificial bulk modulus. The particle keeps its
/// volume (F = I: the schemes do not update it, tracks_deformation): it stores no energy.

#include "mpm/materials/material.hpp"

namespace mpm::fluids {

struct IncompressibleFluid {
  static constexpr const char* key = "incompressible_fluid";
  /// The particle keeps its volume: the schemes leave F = I (Material::tracks_deformation).
  static constexpr bool tracks_deformation = false;
  struct Params {
    Real density;    ///< rho, kg/m^3
    Real viscosity;  ///< mu, Pa s
  };

  /// The viscous stress 2 mu dev(D); the pressure is the projection's (eq. 21.4).
  static inline Mat3 update_point(const Params& c, const PointKinematics& k, const Mat3&) {
    const Mat3 D = 0.5 * (k.L + k.L.transpose());
    return 2 * c.viscosity * (D - D.trace() / 3 * Mat3::Identity());
  }
  /// No pressure wave: the CFL bound reads the particle speed alone (eq. 2.73 with c = 0).
  static inline Real wave_speed(const Params&, Real) { return 0; }
  /// The bound dt <= h^2 / (2 Dim nu) of explicit viscous diffusion, nu = 4 mu / (3 rho) as for the Tait fluid.
  static inline Real kinematic_viscosity(const Params& c) { return 4 * c.viscosity / (3 * c.density); }
  /// An incompressible particle stores nothing: its volume never changes and viscous stresses dissipate.
  static inline Real energy_density(const Params&, const Mat3&, const Mat3&) { return 0; }
};

}  // namespace mpm::fluids
