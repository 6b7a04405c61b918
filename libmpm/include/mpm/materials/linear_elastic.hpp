#pragma once
/// \file linear_elastic.hpp
/// Isotropic linear elasticity in incremental (hypoelastic) form, review eq. B.5, made objective with
/// the Jaumann rate: sigma^{t+dt} = sigma + dt (W sigma - sigma W) + lambda tr(de) I + 2 mu de, with
/// de = dt sym(L) and W = skew(L) (review eq. 2.15). Exact for small strains; rigid rotations leave the
/// stress invariants unchanged to first order in dt.

#include <cmath>

#include "mpm/materials/elastic_constants.hpp"
#include "mpm/materials/material.hpp"

namespace mpm {

struct LinearElastic {
  static constexpr const char* key = "linear_elastic";
  using Params = ElasticConstants;

  static inline Mat3 update_point(const Params& c, const PointKinematics& k, const Mat3& s) {
    const Mat3 de = 0.5 * k.dt * (k.L + k.L.transpose());
    const Mat3 W = 0.5 * (k.L - k.L.transpose());
    return s + k.dt * (W * s - s * W) + c.lambda * de.trace() * Mat3::Identity() + 2 * c.mu * de;
  }
  /// The same law on packed storage: in plane strain (uniaxial strain in 1D) the out-of-plane strain
  /// rate is zero, so the out-of-plane normal stresses only receive lambda tr(de).
  template <int Dim>
  static inline void update_packed(const Params& m, const Mat<Dim>&, const Mat<Dim>& L, Real, Real dt,
                                   SymTensor<Dim>& s) {
    if constexpr (Dim == 2) {
      update_2d<false>(m, L, 0, dt, s);
      return;
    }
    const Mat<Dim> de = 0.5 * dt * (L + L.transpose());
    const Real tr = de.trace();
    Mat<Dim> b = s.block();
    if constexpr (Dim > 1) {
      const Mat<Dim> W = 0.5 * (L - L.transpose());
      b += dt * (W * b - b * W);
    }
    b += m.lambda * tr * Mat<Dim>::Identity() + 2 * m.mu * de;
    s.set_block(b);
    for (int k = Dim; k < 3; ++k) s.c[k] += m.lambda * tr;
  }
  /// Axisymmetric: the hoop strain increment dt L_tt joins the trace and the theta-theta stress.
  static inline void update_packed_axisymmetric(const Params& m, const Mat<2>&, const Mat<2>& L, Real, Real L_tt, Real,
                                                Real dt, SymTensor<2>& s) {
    update_2d<true>(m, L, L_tt, dt, s);
  }
  /// The 2D law written out: with sigma = [[a, c], [c, b]] and W = [[0, w], [-w, 0]],
  /// W sigma - sigma W = [[2wc, w(b - a)], [w(b - a), -2wc]]. (Eigen's 2x2 products here cost a
  /// store-forwarding stall per particle, a quarter of the whole step.) Out of plane: zero strain rate (plane
  /// strain) or, `Hoop`, the hoop rate L_tt; the rotation about the out-of-plane axis leaves that component alone.
  template <bool Hoop>
  static inline void update_2d(const Params& m, const Mat<2>& L, [[maybe_unused]] Real L_tt, Real dt, SymTensor<2>& s) {
    const Real a = s.c[0], b = s.c[1], c = s.c[3];
    const Real w = 0.5 * (L(0, 1) - L(1, 0));
    const Real exx = dt * L(0, 0), eyy = dt * L(1, 1), exy = 0.5 * dt * (L(0, 1) + L(1, 0));
    Real tr = exx + eyy;
    [[maybe_unused]] Real ett = 0;
    if constexpr (Hoop) {
      ett = dt * L_tt;
      tr += ett;
    }
    const Real lt = m.lambda * tr;
    s.c[0] = a + dt * 2 * w * c + lt + 2 * m.mu * exx;
    s.c[1] = b - dt * 2 * w * c + lt + 2 * m.mu * eyy;
    s.c[3] = c + dt * w * (b - a) + 2 * m.mu * exy;
    if constexpr (Hoop)
      s.c[2] += lt + 2 * m.mu * ett;
    else
      s.c[2] += lt;
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
