#pragma once
/// \file equation_of_state.hpp
/// Pressure p (positive in compression) as a function of J = det F = rho0/rho and of the internal energy
/// per unit reference volume e (review App. B.3.1; damage is applied by the stress update, to tension only):
///   LinearEos:       p = K (1 - J).
///   MieGruneisenEos: p = rho0 c0^2 mu [1 + (1 - Gamma0/2) mu] / [1 - (S - 1) mu]^2 + Gamma0 e, mu = 1/J - 1
///                    (eq. B.9 with eta = 1 + mu, linear Us-up Hugoniot Us = c0 + S up). On the Hugoniot,
///                    e = p mu / (2 (1 + mu)), and p equals rho0 Us up.
/// Each also gives the tangent bulk modulus K_t = -J dp/dJ (for the wave speed) and the stored energy
/// per reference volume W(J) = -int_1^J p dJ' at e = 0 (for the energy audit).

#include <algorithm>

#include "mpm/plasticity/lanes.hpp"

namespace mpm::plasticity {

struct LinearEos {
  Real bulk_modulus = 0;  ///< K, Pa

  template <class T>
  T pressure(const T& J, const T& /*e*/) const {
    return bulk_modulus * (1 - J);
  }
  template <class T>
  T tangent_bulk_modulus(const T& J) const {
    return bulk_modulus * J;
  }
  Real energy(Real J) const { return 0.5 * bulk_modulus * (J - 1) * (J - 1); }
};

struct MieGruneisenEos {
  Real density = 0;          ///< rho0, kg/m^3
  Real sound_speed = 0;      ///< c0, m/s
  Real hugoniot_slope = 0;   ///< S, -
  Real gruneisen_gamma = 0;  ///< Gamma0, -

  template <class T>
  T pressure(const T& J, const T& e) const {
    const T mu = 1 / J - 1;
    const T den = 1 - (hugoniot_slope - 1) * mu;
    return density * sound_speed * sound_speed * mu * (1 + (1 - 0.5 * gruneisen_gamma) * mu) / (den * den) +
           gruneisen_gamma * e;
  }
  /// -J dp/dJ = (1 + mu) dp/dmu at e fixed.
  template <class T>
  T tangent_bulk_modulus(const T& J) const {
    const Real k = hugoniot_slope - 1, g = 1 - 0.5 * gruneisen_gamma;
    const T mu = 1 / J - 1;
    const T den = 1 - k * mu;
    const T num = mu * (1 + g * mu), dnum = 1 + 2 * g * mu;
    const T dp = density * sound_speed * sound_speed * (dnum * den + 2 * k * num) / (den * den * den);
    return lanes::max(T((1 + mu) * dp), Real(0));
  }
  /// Five-point Gauss-Legendre quadrature of -int_1^J p(J', 0) dJ' (exact to ~1e-9 relative for |J - 1| < 0.3).
  Real energy(Real J) const {
    static constexpr Real x[5] = {-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640};
    static constexpr Real w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                  0.2369268850561891};
    const Real half = 0.5 * (J - 1), mid = 0.5 * (J + 1);
    Real sum = 0;
    for (int k = 0; k < 5; ++k) sum += w[k] * pressure<Real>(mid + half * x[k], 0);
    return -half * sum;
  }
};

}  // namespace mpm::plasticity
