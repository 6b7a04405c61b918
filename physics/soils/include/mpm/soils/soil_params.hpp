#pragma once
/// \file soil_params.hpp
/// The constants of a frictional soil (drucker_prager, mohr_coulomb, mu_i), built once from the scene: isotropic
/// elasticity, friction and dilation angles, cohesion and the tension cut-off (docs/theory.md §18); for mu_i the
/// constants of the mu(I) rheology (eqs. 18.20-18.24).

#include <algorithm>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm::soils {

/// How a Drucker-Prager cone is fitted to the Mohr-Coulomb pyramid of the same friction angle and cohesion
/// (de Souza Neto, Peric & Owen 2008, §6.4.6; theory eq. 18.3). The index is the value of the scene key
/// cone_matching.
enum class ConeMatching {
  outer_cone = 0,    ///< through the compressive meridians (triaxial compression agrees with Mohr-Coulomb)
  inner_cone = 1,    ///< through the tensile meridians (triaxial extension agrees)
  plane_strain = 2,  ///< the same plane-strain collapse load as Mohr-Coulomb (associated flow)
};

/// The coefficients of sqrt(J2) + eta p - xi c (p = tr(sigma)/3, tension positive) for a friction angle `phi`
/// (rad), theory eq. 18.3.
struct ConeCoefficients {
  Real eta = 0;
  Real xi = 0;
};

inline ConeCoefficients cone_coefficients(ConeMatching matching, Real phi) {
  const Real s = std::sin(phi), c = std::cos(phi), root3 = std::sqrt(Real(3));
  switch (matching) {
    case ConeMatching::outer_cone:
      return {6 * s / (root3 * (3 - s)), 6 * c / (root3 * (3 - s))};
    case ConeMatching::inner_cone:
      return {6 * s / (root3 * (3 + s)), 6 * c / (root3 * (3 + s))};
    case ConeMatching::plane_strain: {
      const Real t = std::tan(phi), d = std::sqrt(9 + 12 * t * t);
      return {3 * t / d, 3 / d};
    }
  }
  return {};
}

/// Linear softening of the strength with the equivalent plastic strain eps_p (theory eq. 18.19): c and phi go from
/// their peak values at eps_p = 0 to their residual values at eps_p = strain, and stay there.
struct Softening {
  bool enabled = false;
  Real residual_cohesion = 0;  ///< Pa
  Real residual_friction = 0;  ///< rad
  Real strain = 1;             ///< eps_p at which the residual values are reached, -
};

/// The mu(I) rheology of Jop, Forterre & Pouliquen (2006), with the paper's names (theory eq. 18.20):
/// mu(I) = mu_s + (mu_2 - mu_s) / (I_0 / I + 1), I = gamma_dot d / sqrt(P / rho_s).
struct GranularRheology {
  Real mu_s = 0;            ///< static friction coefficient (tan of the angle at which flow starts), -
  Real mu_2 = 0;            ///< limiting friction coefficient at large I, >= mu_s, -
  Real I_0 = 1;             ///< the inertial number at which mu is halfway between mu_s and mu_2, -
  Real grain_diameter = 0;  ///< d, m
  Real grain_density = 0;   ///< rho_s, the density of the grains' material, kg/m^3

  /// mu(I) (eq. 18.20), written so that I = 0 gives mu_s exactly.
  Real friction(Real I) const { return mu_s + (mu_2 - mu_s) * I / (I_0 + I); }
  /// The inertial number of a shear rate |gamma_dot| (1/s) at a pressure P > 0 (Pa), eq. 18.20.
  Real inertial_number(Real shear_rate, Real pressure) const {
    return shear_rate * grain_diameter * std::sqrt(grain_density / pressure);
  }
};

struct SoilParams {
  Real density = 0;         ///< kg/m^3
  Real shear_modulus = 0;   ///< G, Pa
  Real bulk_modulus = 0;    ///< K, Pa
  Real friction = 0;        ///< friction angle phi, rad
  Real dilation = 0;        ///< dilation angle psi, rad (<= phi)
  Real cohesion = 0;        ///< c, Pa
  Real tension_cutoff = 0;  ///< T: the mean stress p = tr(sigma)/3 never exceeds min(T, apex), Pa
  ConeMatching matching = ConeMatching::plane_strain;  ///< Drucker-Prager only
  Softening softening;
  GranularRheology granular;  ///< mu_i only

  /// The constants at the equivalent plastic strain eps_p: c and phi softened linearly (eq. 18.19), psi kept at or
  /// below phi.
  SoilParams softened(Real eps_p) const {
    SoilParams p = *this;
    const Real t = std::min(eps_p / softening.strain, Real(1));
    p.cohesion = cohesion + t * (softening.residual_cohesion - cohesion);
    p.friction = friction + t * (softening.residual_friction - friction);
    p.dilation = std::min(dilation, p.friction);
    return p;
  }

  /// Dilatational wave speed sqrt((K + 4G/3)/rho), m/s: plastic flow only softens the response.
  Real wave_speed() const { return std::sqrt((bulk_modulus + 4 * shear_modulus / 3) / density); }
};

}  // namespace mpm::soils
