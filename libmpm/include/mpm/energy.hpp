#pragma once
/// \file energy.hpp
/// Conservation audit (DESIGN.md): energies, linear momentum and mass of all bodies.

#include "mpm/types.hpp"

namespace mpm {

struct EnergyBalance {
  Real kinetic = 0;       ///< J: 1/2 sum m v.v
  Real strain = 0;        ///< J: stored elastic energy (review eq. 6.5)
  Real gravity = 0;       ///< J: potential of the body force, -sum m g.x
  Real plastic_work = 0;  ///< J: energy dissipated by plastic flow (plasticity module)
  /// J: heat stored, sum m c (T - T_ref) (thermal module). Not in total(): with plastic heating it holds the
  /// fraction chi of plastic_work (already counted there) plus the heat conducted in through the boundary.
  Real thermal = 0;
  Vec3 momentum = Vec3::Zero();  ///< kg m/s
  Real mass = 0;                 ///< kg
  Real total() const { return kinetic + strain + gravity + plastic_work; }
};

}  // namespace mpm
