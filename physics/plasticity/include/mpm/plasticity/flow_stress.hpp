#pragma once
/// \file flow_stress.hpp
/// Flow stress laws sigma_f(eps_p, rate*, T*) of the J2 models (review App. B.3.2, Table 9):
///   HardeningFlow:   sigma_y + H eps_p + Q (1 - exp(-b eps_p))   (perfectly plastic: H = Q = 0; linear: Q = 0;
///                    Voce: H = 0). No rate or temperature dependence.
///   JohnsonCookFlow: [A + B eps_p^n] [1 + C ln rate*] [1 - T*^m]   (eq. B.11), rate* = max(rate/rate0, 1)
///                    (so that the logarithm is never negative), T* = (T - T_r)/(T_m - T_r) in [0, 1].
/// Damage scales the result by (1 - D) in the stress update, not here. Each law also gives its slope
/// d sigma_f / d eps_p (at fixed rate and temperature), used by tests (Considere strain). hardening and
/// factor take one point (Real) or a pack of them (lanes.hpp).

#include <cmath>

#include "mpm/plasticity/lanes.hpp"

namespace mpm::plasticity {

struct HardeningFlow {
  Real yield_stress = 0;       ///< sigma_y, Pa
  Real hardening_modulus = 0;  ///< H, Pa
  Real saturation_stress = 0;  ///< Voce Q, Pa
  Real saturation_rate = 0;    ///< Voce b, -

  /// The strain-hardening part (what a history cache keeps), and the factor of rate and temperature.
  template <class T>
  T hardening(const T& eps_p) const {
    T s = yield_stress + hardening_modulus * eps_p;
    if (saturation_stress != 0) {
      const T decay = lanes::exp(T(-saturation_rate * eps_p));
      s = s + saturation_stress * (1 - decay);
    }
    return s;
  }
  template <class T>
  T factor(const T& /*rate_star*/, const T& /*T_star*/) const {
    return lanes::splat<T>(1);
  }
  Real stress(Real eps_p, Real rate_star, Real T_star) const { return hardening(eps_p) * factor(rate_star, T_star); }
  Real slope(Real eps_p) const {
    return hardening_modulus + saturation_stress * saturation_rate * std::exp(-saturation_rate * eps_p);
  }
};

struct JohnsonCookFlow {
  Real A = 0;  ///< yield stress, Pa
  Real B = 0;  ///< hardening coefficient, Pa
  Real n = 1;  ///< hardening exponent, -
  Real C = 0;  ///< strain-rate coefficient, -
  Real m = 1;  ///< thermal softening exponent, -

  template <class T>
  T hardening(const T& eps_p) const {
    const MaskOf<T> hardened = eps_p > 0;
    if (!lanes::any(hardened)) return lanes::splat<T>(A);
    const T eps_n = lanes::power(lanes::max(eps_p, Real(0)), n);
    return lanes::select(hardened, T(A + B * eps_n), A);
  }
  /// rate* below 1 counts as 1 (eq. B.11 as used here: the logarithm is never negative), T* in [0, 1].
  template <class T>
  T factor(const T& rate_star, const T& T_star) const {
    T f = lanes::splat<T>(1);
    if (C != 0) {
      const T ln_rate = lanes::log(lanes::max(rate_star, Real(1)));
      f = 1 + C * ln_rate;
    }
    if (lanes::any(MaskOf<T>(T_star > 0))) {
      const T soft = 1 - lanes::power(T_star, m);
      f = f * lanes::select(MaskOf<T>(T_star < 1), soft, 0);
    }
    return f;
  }
  Real stress(Real eps_p, Real rate_star, Real T_star) const { return hardening(eps_p) * factor(rate_star, T_star); }
  /// d sigma_f / d eps_p at rate* = 1 and T* = 0.
  Real slope(Real eps_p) const { return B * n * std::pow(eps_p, n - 1); }
};

}  // namespace mpm::plasticity
