#pragma once
/// \file local_damping.hpp
/// Local non-viscous damping of the grid momentum update (Cundall 1987; the "local damping" of FLAC, Anura3D and
/// cb-geo; docs/theory.md eq. 2.74): each component of a node's unbalanced force f is reduced by alpha |f_c| against
/// the node's velocity at the start of the step. It removes kinetic energy in proportion to the force that is still
/// out of balance, so a body settles to its static state without a viscosity that would also act on a steady
/// motion, and vanishes with the unbalanced force: the equilibrium it reaches is the undamped one.

#include <cmath>

#include "mpm/core/types.hpp"

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

}  // namespace mpm::kernels
