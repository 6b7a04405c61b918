#pragma once
/// \file drucker_prager.hpp
/// The return mapping of the perfectly plastic Drucker-Prager cone with non-associated flow and a tension cut-off
/// (docs/theory.md §18, eqs. 18.1-18.7). The algorithm is that of de Souza Neto, Peric & Owen, Computational Methods
/// for Plasticity (2008), §8.3: a return to the smooth portion of the cone in closed form (eqs. 18.5), and, when that
/// return passes the apex, the return to the apex (eq. 18.6); here the apex is the cone cut by the tension cut-off
/// plane p = T whenever T is below the cone's own apex xi c / eta (eq. 18.7). Small-strain in form: the trial stress
/// comes from the hypoelastic update of soil_batch.hpp.

#include <algorithm>
#include <cmath>
#include <limits>

#include "mpm/soils/soil_params.hpp"

namespace mpm::soils {

class DruckerPrager {
 public:
  static constexpr const char* key = "drucker_prager";

  explicit DruckerPrager(const SoilParams& p) : G_(p.shear_modulus), K_(p.bulk_modulus), cohesion_(p.cohesion) {
    const ConeCoefficients yield = cone_coefficients(p.matching, p.friction);
    eta_ = yield.eta;
    xi_ = yield.xi;
    eta_bar_ = cone_coefficients(p.matching, p.dilation).eta;  // the flow potential's cone (eq. 18.4)
    const Real apex = eta_ > 0 ? xi_ * cohesion_ / eta_ : std::numeric_limits<Real>::infinity();
    cap_ = std::min(p.tension_cutoff, apex);
  }

  /// The yield function sqrt(J2) + eta p - xi c of a stress (eq. 18.1), Pa.
  Real yield_function(const Mat3& sigma) const {
    const Real p = sigma.trace() / 3;
    const Mat3 s = sigma - p * Mat3::Identity();
    return std::sqrt(0.5 * s.squaredNorm()) + eta_ * p - xi_ * cohesion_;
  }
  /// The largest mean stress the material carries, min(T, xi c / eta), Pa.
  Real mean_stress_cap() const { return cap_; }
  Real eta() const { return eta_; }
  Real xi() const { return xi_; }
  Real eta_bar() const { return eta_bar_; }

  /// The stress returned from the elastic trial stress (tension positive), Pa.
  Mat3 return_map(const Mat3& trial) const {
    const Real p_trial = trial.trace() / 3;
    const Mat3 s_trial = trial - p_trial * Mat3::Identity();
    const Real q_trial = std::sqrt(0.5 * s_trial.squaredNorm());  // sqrt(J2)
    const Real phi = q_trial + eta_ * p_trial - xi_ * cohesion_;
    if (phi <= 0 && p_trial <= cap_) return trial;  // elastic
    if (phi > 0) {
      // Smooth portion of the cone, perfectly plastic: Delta gamma = Phi / (G + K eta eta_bar) (eq. 18.5a).
      const Real gamma = phi / (G_ + K_ * eta_ * eta_bar_);
      if (q_trial - G_ * gamma >= 0) {
        const Real p = p_trial - K_ * eta_bar_ * gamma;  // eq. 18.5b
        if (p <= cap_) return (1 - G_ * gamma / q_trial) * s_trial + p * Mat3::Identity();
      }
    }
    // Apex (eq. 18.6) or the edge of the cone and the cut-off plane (eq. 18.7): p = cap; the deviator is scaled onto
    // the cone's radius there (the cone's flow is radial in the deviatoric plane, the cut-off's purely volumetric).
    const Real radius = std::max(Real(0), xi_ * cohesion_ - eta_ * cap_);
    const Real scale = q_trial > radius ? radius / q_trial : 1;
    return scale * s_trial + cap_ * Mat3::Identity();
  }

 private:
  Real G_, K_, cohesion_;
  Real eta_ = 0, xi_ = 0, eta_bar_ = 0, cap_ = 0;
};

}  // namespace mpm::soils
