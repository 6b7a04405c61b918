#pragma once
/// \file log_volumetric_energy.hpp
/// The volumetric energy U(Theta) = K/2 ln^2 Theta of the Hencky model (ref. 003 eqs. 43, 49). The paper
/// leaves U open; this is the logarithmic form that matches the Hencky deviatoric energy G ||dev eps^e||^2
/// (the energy is quadratic in the logarithmic strain, U = K/2 (tr eps^e)^2 at Theta = J^e = J).
/// Theta is the mixed volume of the three-field form (eq. 11) in the implicit scheme and J in the explicit
/// ones; the mixed pressure is p = U'(Theta) = K ln(Theta) / Theta (eq. 13b) and the Kirchhoff pressure
/// Theta U' = K ln Theta.
///
/// The discrete derivative D_Theta U(Theta_1, Theta_2) of eq. (88c) is the secant slope, written without a
/// 0/0: with x = (Theta_2 - Theta_1)/Theta_1, l_1 = ln Theta_1 and l_2 = l_1 + log1p(x),
///   Delta U = K/2 (l_2 - l_1)(l_2 + l_1) = K/2 log1p(x) (l_1 + l_2),
///   D_Theta U = K/2 (l_1 + l_2) [log1p(x)/x] / Theta_1,
/// and log1p(x)/x by its series for |x| < 1e-4. So D_Theta U Delta Theta = Delta U to round-off for every
/// pair (directionality, Def. 3.1), D_Theta U = U'(Theta_1) exactly when Theta_2 = Theta_1, and
/// D_Theta U = U'((Theta_1 + Theta_2)/2) + O(Delta Theta^2) (consistency).

#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm::plasticity {

/// log1p(x)/x, smooth through x = 0 (value 1): the series 1 - x/2 + x^2/3 - x^3/4 + x^4/5 below |x| = 1e-4
/// (truncation below x^5/6 < 2e-21), the quotient above.
inline Real log1p_over_x(Real x) {
  if (std::abs(x) < 1e-4) return 1 + x * (-0.5 + x * (1.0 / 3 + x * (-0.25 + x * 0.2)));
  return std::log1p(x) / x;
}

/// U(Theta) = K/2 ln^2 Theta with its derivative and discrete derivative. Theta > 0 (dimensionless).
struct LogVolumetricEnergy {
  Real bulk_modulus = 0;  ///< K, Pa

  /// U(Theta), J/m^3 of reference volume.
  Real energy(Real theta) const {
    const Real l = std::log(theta);
    return 0.5 * bulk_modulus * l * l;
  }
  /// U'(Theta) = K ln(Theta) / Theta: the mixed (Cauchy-like) pressure p, positive in tension, Pa.
  Real derivative(Real theta) const { return bulk_modulus * std::log(theta) / theta; }
  /// Theta U'(Theta) = K ln Theta: the Kirchhoff pressure, Pa.
  Real kirchhoff_pressure(Real theta) const { return bulk_modulus * std::log(theta); }
  /// U(Theta_2) - U(Theta_1) without cancellation in ln Theta_2 - ln Theta_1, J/m^3.
  Real difference(Real theta_1, Real theta_2) const {
    const Real x = (theta_2 - theta_1) / theta_1, l1 = std::log(theta_1), dl = std::log1p(x);
    return 0.5 * bulk_modulus * dl * (2 * l1 + dl);
  }
  /// D_Theta U(Theta_1, Theta_2) (eqs. 88c, 104): D_Theta U (Theta_2 - Theta_1) = U(Theta_2) - U(Theta_1),
  /// finite for Theta_2 = Theta_1 (then U'(Theta_1)), Pa.
  Real discrete_derivative(Real theta_1, Real theta_2) const {
    const Real x = (theta_2 - theta_1) / theta_1, l1 = std::log(theta_1), dl = std::log1p(x);
    return 0.5 * bulk_modulus * (2 * l1 + dl) * log1p_over_x(x) / theta_1;
  }
};

}  // namespace mpm::plasticity
