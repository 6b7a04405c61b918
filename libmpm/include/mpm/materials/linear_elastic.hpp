#pragma once
/// \file linear_elastic.hpp
/// Isotropic linear elasticity in incremental (hypoelastic) form, review eq. B.5, made objective with
/// the Jaumann rate: sigma^{t+dt} = sigma + dt (W sigma - sigma W) + lambda tr(de) I + 2 mu de, with
/// de = dt sym(L) and W = skew(L) (review eq. 2.15). Exact for small strains; rigid rotations leave the
/// stress invariants unchanged to first order in dt.

#include <cmath>

#include "mpm/material.hpp"
#include "mpm/materials/elastic_constants.hpp"

namespace mpm {

struct LinearElastic {
  static constexpr const char* key = "linear_elastic";
  using Params = ElasticConstants;

  static inline Mat3 update_point(const Params& c, const PointKinematics& k, const Mat3& s) {
    const Mat3 de = 0.5 * k.dt * (k.L + k.L.transpose());
    const Mat3 W = 0.5 * (k.L - k.L.transpose());
    return s + k.dt * (W * s - s * W) + c.lambda * de.trace() * Mat3::Identity() + 2 * c.mu * de;
  }
  /// Dilatational wave speed sqrt((lambda + 2 mu)/rho) with rho = rho0/J (eq. 2.71).
  static inline Real wave_speed(const Params& c, Real J) {
    return std::sqrt((c.lambda + 2 * c.mu) * std::max(J, Real(0)) / c.density);
  }
  /// Elastic energy per reference volume: J * (1/2) sigma : C^-1 : sigma (review eq. 6.5, with the
  /// strain recovered from the stress so that no strain field is stored).
  static inline Real energy_density(const Params& c, const Mat3& F, const Mat3& s) {
    const Real tr = s.trace();
    const Mat3 dev = s - tr / 3 * Mat3::Identity();
    return F.determinant() * (tr * tr / (18 * c.bulk) + dev.squaredNorm() / (4 * c.mu));
  }
};

}  // namespace mpm
