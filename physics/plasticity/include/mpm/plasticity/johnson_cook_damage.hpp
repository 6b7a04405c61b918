#pragma once
/// \file johnson_cook_damage.hpp
/// Johnson-Cook damage (review App. B.3.3, Alg. 13, with the digest's errata 27):
///   eps_f = [D1 + D2 exp(D3 sigma*)] [1 + D4 ln rate*] [1 + D5 T*]   (eq. B.15), sigma* = sigma_m / sigma_eq,
///   D_init += d eps_p / eps_f                                        (eq. B.14),
///   D = min(1, k (D_init - 1)) once D_init >= 1                      (eq. B.16, k = 10 in the review; the
///                                                                      factor is missing in Alg. 13 line 7).
/// So damage starts when the plastic strain reaches eps_f and is complete at (1 + 1/k) eps_f under constant
/// triaxiality. rate* = max(rate / rate0, 1); eps_f is kept above 1e-6 so that a strongly negative
/// triaxiality term cannot make it vanish.

#include <algorithm>
#include <cmath>

#include "mpm/types.hpp"

namespace mpm::plasticity {

struct JohnsonCookDamage {
  Real d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0;  ///< -
  Real evolution_factor = 10;                   ///< k of eq. B.16

  /// Equivalent plastic strain at failure for triaxiality sigma*, rate* >= 1, T* in [0, 1].
  Real failure_strain(Real triaxiality, Real rate_star, Real T_star) const {
    Real eps = d1 + d2 * std::exp(d3 * triaxiality);
    if (d4 != 0) eps *= 1 + d4 * std::log(rate_star);
    if (d5 != 0) eps *= 1 + d5 * T_star;
    return std::max(eps, Real(1e-6));
  }
  /// Damage D for an initiation indicator D_init.
  Real damage(Real initiation) const {
    return initiation < 1 ? Real(0) : std::min(Real(1), evolution_factor * (initiation - 1));
  }
};

}  // namespace mpm::plasticity
