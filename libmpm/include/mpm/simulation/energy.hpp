#pragma once
/// \file energy.hpp
/// Conservation audit (DESIGN.md): energies, linear momentum and mass of all bodies.

#include <array>

#include "mpm/core/exact_sum.hpp"
#include "mpm/core/types.hpp"
#include "mpm/parallel/communicator.hpp"

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

/// The terms of an EnergyBalance as they are gathered, each summed exactly (exact_sum.hpp): the balance
/// (value()) is then the same bits for any storage order of the particles, any thread count and any split of
/// the particles into parts whose sums are merged (MPI ranks), docs/distributed.md §1.
struct EnergySums {
  ExactSum kinetic, strain, gravity, plastic_work, thermal, mass;
  std::array<ExactSum, 3> momentum;
  void merge(const EnergySums& o) {
    kinetic.merge(o.kinetic);
    strain.merge(o.strain);
    gravity.merge(o.gravity);
    plastic_work.merge(o.plastic_work);
    thermal.merge(o.thermal);
    mass.merge(o.mass);
    for (int d = 0; d < 3; ++d) momentum[d].merge(o.momentum[d]);
  }
  /// Every rank's sums merged (a distributed run): the bits of one sum over all ranks' particles.
  void reduce(Communicator& comm) {
    std::array<ExactSum, 9> all{kinetic, strain,      gravity,     plastic_work, thermal,
                                mass,    momentum[0], momentum[1], momentum[2]};
    comm.sum(all);
    kinetic = all[0];
    strain = all[1];
    gravity = all[2];
    plastic_work = all[3];
    thermal = all[4];
    mass = all[5];
    for (int d = 0; d < 3; ++d) momentum[d] = all[6 + d];
  }
  EnergyBalance value() const {
    EnergyBalance e;
    e.kinetic = kinetic.value();
    e.strain = strain.value();
    e.gravity = gravity.value();
    e.plastic_work = plastic_work.value();
    e.thermal = thermal.value();
    e.mass = mass.value();
    for (int d = 0; d < 3; ++d) e.momentum[d] = momentum[d].value();
    return e;
  }
};

}  // namespace mpm
