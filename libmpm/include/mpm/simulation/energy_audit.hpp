#pragma once
/// \file energy_audit.hpp
/// One body's share of the conservation audit (energy.hpp), for Simulation::energy() and the energy sentinel
/// (energy_sentinel.hpp), which both sum the same terms: kinetic 1/2 m v.v, the potential -m g.x of gravity, the
/// material's strain and dissipated energy and the modules' shares (heat), one exactly summed term per particle.

#include <memory>
#include <vector>

#include "mpm/particles/body.hpp"
#include "mpm/simulation/energy.hpp"
#include "mpm/simulation/module.hpp"

namespace mpm {

/// Adds the audit of `b` under `gravity` (m/s^2) to `e`, with the shares of `modules`.
template <int Dim>
void add_body_energy(const Body<Dim>& b, const Vec<Dim>& gravity,
                     const std::vector<std::shared_ptr<Module<Dim>>>& modules, EnergySums& e) {
  // One exactly summed term per particle and quantity: the audit is the same bits for any storage order
  // (sorting, shuffled input) and any split of the particles (threads, ranks): docs/distributed.md §1.
  const auto& p = b.particles;
  for (Index i = 0; i < p.size(); ++i) {
    const Real m = p.mass[i];
    e.kinetic += 0.5 * m * p.v[i].squaredNorm();
    e.gravity += -(m * gravity.dot(Vec<Dim>(p.x[i])));
    for (int d = 0; d < Dim; ++d) e.momentum[d] += m * p.v[i][d];
    e.mass += m;
  }
  b.material->add_strain_energy(p, e.strain);
  b.material->add_dissipated_energy(p, e.plastic_work);
  for (const auto& m : modules) m->add_energy(b, e);
}

}  // namespace mpm
