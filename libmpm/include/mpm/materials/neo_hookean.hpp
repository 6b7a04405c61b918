#pragma once
/// \file neo_hookean.hpp
/// Compressible Neo-Hookean hyperelasticity (review App. B.2, Bonet & Wood):
///   sigma = [mu (F F^T - I) + lambda ln(J) I] / J                                   (eq. B.7)
///   W(F)  = mu/2 (tr(F^T F) - 3) - mu ln J + lambda/2 (ln J)^2   per reference volume.

#include <algorithm>
#include <cmath>

#include "mpm/materials/elastic_constants.hpp"
#include "mpm/materials/material.hpp"

namespace mpm {

struct NeoHookean {
  static constexpr const char* key = "neo_hookean";
  using Params = ElasticConstants;

  static inline Mat3 update_point(const Params& c, const PointKinematics& k, const Mat3&) {
    const Mat3 b = k.F * k.F.transpose();
    return (c.mu * (b - Mat3::Identity()) + c.lambda * std::log(k.J) * Mat3::Identity()) / k.J;
  }
  /// The same law on packed storage (out-of-plane stretch 1, so b_zz = 1 and sigma_zz = lambda ln J / J).
  template <int Dim>
  static inline void update_packed(const Params& c, const Mat<Dim>& F, const Mat<Dim>&, Real J, Real,
                                   SymTensor<Dim>& s) {
    const Real inv_J = 1 / J, p = c.lambda * std::log(J);
    s.set_block((c.mu * (F * F.transpose() - Mat<Dim>::Identity()) + p * Mat<Dim>::Identity()) * inv_J);
    for (int k = Dim; k < 3; ++k) s.c[k] = p * inv_J;
  }
  /// Speed of the linearised dilatational wave about the current state: the spatial moduli are
  /// lambda/J and (mu - lambda ln J)/J and rho = rho0/J, so c^2 = (lambda + 2 mu - 2 lambda ln J)/rho0,
  /// never taken below its undeformed value.
  static inline Real wave_speed(const Params& c, Real J) {
    const Real m = c.lambda + 2 * c.mu;
    return std::sqrt(std::max(m, m - 2 * c.lambda * std::log(J)) / c.density);
  }
  static inline Real energy_density(const Params& c, const Mat3& F, const Mat3&) {
    const Real lnJ = std::log(F.determinant());
    return 0.5 * c.mu * ((F.transpose() * F).trace() - 3) - c.mu * lnJ + 0.5 * c.lambda * lnJ * lnJ;
  }
};

}  // namespace mpm
