#pragma once
/// \file contact_law.hpp
/// The velocity correction at one contact node for one body (review §5.1, Bardenhagen et al. 2000, 2001):
/// frictionless (eq. 5.5) and Coulomb friction (eqs 5.6-5.8, written without cross products so that the
/// same code serves 2D and 3D). Inline and free of grid data, so that it can be unit-tested alone.

#include <algorithm>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm::contact {

/// Corrects the velocity `v` of body k at a node where it meets bodies moving with the centre-of-mass
/// velocity `v_cm` (eq. 5.3; the rigid body's velocity when one is present); `n` is body k's outward unit
/// normal and `mu` the friction coefficient. Returns false (and leaves v unchanged) on release, i.e. when
/// D = (v - v_cm).n <= 0 (eq. 5.2: the bodies separate or slide along each other).
///
/// With dv = v - v_cm and the tangential slip t = dv - D n:
///   v <- v - D n - mu' D t/|t|,  mu' = min(mu, |t| / D)            (eqs 5.6-5.7)
/// which is eq. 5.5 for mu = 0, and full stick (v = v_cm) when friction can stop the slip (mu' = |t|/D).
/// In 2D t/|t| is the unit vector of eq. 5.8 ([n_y C, -n_x C]/|C| with C = dv_x n_y - dv_y n_x).
template <int Dim>
inline bool correct_velocity(Vec<Dim>& v, const Vec<Dim>& v_cm, const Vec<Dim>& n, Real mu) {
  const Vec<Dim> dv = v - v_cm;
  const Real D = dv.dot(n);
  if (!(D > 0)) return false;
  v -= D * n;
  if (mu > 0) {
    const Vec<Dim> t = dv - D * n;
    const Real slip = t.norm();
    if (slip > 0) {
      const Real mu_eff = std::min(mu, slip / D);
      v -= (mu_eff * D / slip) * t;
    }
  }
  return true;
}

}  // namespace mpm::contact
