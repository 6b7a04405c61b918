#pragma once
/// \file johnson_cook_damage.hpp
/// Johnson-Cook damage (review App. B.3.3, Alg. 13, with docs/errata.md #27):
///   eps_f = [D1 + D2 exp(D3 sigma*)] [1 + D4 ln rate*] [1 + D5 T*]   (eq. B.15), sigma* = sigma_m / sigma_eq,
///   D_init += d eps_p / eps_f                                        (eq. B.14),
///   D = min(1, k (D_init - 1)) once D_init >= 1                      (eq. B.16, k = 10 in the review; the
///                                                                      factor is missing in Alg. 13 line 7).
/// So damage starts when the plastic strain reaches eps_f and is complete at (1 + 1/k) eps_f under constant
/// triaxiality. rate* = max(rate / rate0, 1); eps_f is kept above 1e-6 so that a strongly negative
/// triaxiality term cannot make it vanish.

#include <algorithm>
#include <cmath>

#include "mpm/plasticity/lanes.hpp"

namespace mpm::plasticity {

struct JohnsonCookDamage {
  Real d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0;  ///< -
  Real evolution_factor = 10;                   ///< k of eq. B.16

  /// Equivalent plastic strain at failure for triaxiality sigma*, rate* >= 1, T* in [0, 1].
  /// One point (Real) or a pack of them (lanes.hpp).
  template <class T>
  T failure_strain(const T& triaxiality, const T& rate_star, const T& T_star) const {
    const T growth = lanes::exp(T(d3 * triaxiality));
    T eps = d1 + d2 * growth;
    if (d4 != 0) {
      const T ln_rate = lanes::log(rate_star);
      eps = eps * (1 + d4 * ln_rate);
    }
    if (d5 != 0) eps = eps * (1 + d5 * T_star);
    return lanes::max(eps, Real(1e-6));
  }
  Real failure_strain(Real triaxiality, Real rate_star, Real T_star) const {
    return failure_strain<Real>(triaxiality, rate_star, T_star);
  }
  /// Damage D for an initiation indicator D_init.
  template <class T>
  T damage(const T& initiation) const {
    const T grown = lanes::min(T(evolution_factor * (initiation - 1)), Real(1));
    return lanes::select(MaskOf<T>(initiation < 1), Real(0), grown);
  }
};

}  // namespace mpm::plasticity
