#pragma once
/// \file local_damping.hpp
/// Local non-viscous damping of the grid momentum update (Cundall 1987; the "local damping" of FLAC, Anura3D and
/// cb-geo; docs/theory.md eq. 2.74): each component of a node's unbalanced force f is reduced by alpha |f_c| against
/// the node's velocity at the start of the step. It removes kinetic energy in proportion to the force that is still
/// out of balance, so a body settles to its static state without a viscosity that would also act on a steady
/// motion, and vanishes with the unbalanced force: the equilibrium it reaches is the undamped one.

#include <cmath>

#include "mpm/core/types.hpp"
#include "mpm/grid/grid.hpp"

namespace mpm::kernels {

/// The damping force of eq. 2.74, f_d,c = -alpha |f_c| sign(v_c) per component (0 where v_c = 0): `f` the
/// unbalanced nodal force (internal + external + m g, N), `v` the nodal velocity v^t (m/s), alpha in [0, 1).
template <int Dim>
inline Vec<Dim> local_damping_force(const Vec<Dim>& f, const Vec<Dim>& v, Real alpha) {
  Vec<Dim> d;
  for (int c = 0; c < Dim; ++c) {
    const Real size = alpha * std::abs(f[c]);
    d[c] = v[c] > 0 ? -size : (v[c] < 0 ? size : Real(0));
  }
  return d;
}

/// v^{t+dt} = v^t + dt (f + f_d(f, v^t)) / m (eq. 2.74) for a node of mass m > 0; `f` the unbalanced force.
template <int Dim>
inline Vec<Dim> damped_velocity(const Vec<Dim>& v, const Vec<Dim>& f, Real mass, Real dt, Real alpha) {
  return v + dt / mass * (f + local_damping_force<Dim>(f, v, alpha));
}

/// Multi-velocity fields (contact): the damping acceleration of node I, eq. 2.74 applied to the sum of the fields
/// present there (mass above `cutoff`),
///   a_d = f_d(F, V) / M,  M = sum m_j,  F = sum (f_j + m_j g),  V = sum m_j v_j^t / M
/// (v^t: each field's `mapped` velocity); each field k gets f_d,k = m_k a_d. The contact forces between the fields
/// cancel in F, so the damping vanishes at equilibrium where the bodies press on each other (each field's own force
/// does not: it lacks the contact force), and it gives every field at the node the same acceleration, so it makes no
/// relative motion between bodies. Zero where no field has mass. `for_each_field(visit)` calls visit(grid) for every
/// damped field (rigid bodies, which move as prescribed, are not among them).
template <int Dim, class ForEachField>
Vec<Dim> shared_damping_acceleration(Index I, const Vec<Dim>& gravity, Real cutoff, Real alpha,
                                     ForEachField&& for_each_field) {
  Real mass = 0;
  Vec<Dim> momentum = Vec<Dim>::Zero(), force = Vec<Dim>::Zero();
  for_each_field([&](const Grid<Dim>& grid) {
    const NodeRecord<Dim>& n = grid.node[I];
    if (!(n.mass > cutoff)) return;
    mass += n.mass;
    momentum += n.mass * Vec<Dim>(grid.velocity[I].mapped);
    force += n.force + n.mass * gravity;
  });
  if (!(mass > 0)) return Vec<Dim>::Zero();
  return local_damping_force<Dim>(force, momentum / mass, alpha) / mass;
}

}  // namespace mpm::kernels
