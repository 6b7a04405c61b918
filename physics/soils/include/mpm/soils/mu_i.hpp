#pragma once
/// \file mu_i.hpp
/// The mu(I) rheology of dense granular flow (Jop, Forterre & Pouliquen 2006, Nature 441, 727-730) as an
/// elastic-viscoplastic material point law in the form of Dunatunga & Kamrin (2015, J. Fluid Mech. 779, 483-513):
/// an elastic predictor (the hypoelastic trial stress of soil_batch.hpp, eq. 18.12), no tension (the open,
/// disconnected state: zero stress from the step whose trial pressure is not compressive until the grains have been
/// compressed back by the volume strain they opened by, Dunatunga & Kamrin's rho < rho_c, eq. 18.23), rest while
/// sqrt(J2) <= mu_s P, and otherwise an isochoric plastic flow along the deviator whose equivalent shear rate
/// gamma_dot_p makes the relaxed stress sit on mu(I) P with I taken from gamma_dot_p itself (eqs. 18.21-18.22): one
/// quadratic equation, solved in closed form (docs/theory.md §18, eqs. 18.20-18.24).

#include <algorithm>
#include <cmath>
#include <limits>

#include "mpm/soils/soil_params.hpp"

namespace mpm::soils {

class MuI {
 public:
  static constexpr const char* key = "mu_i";

  explicit MuI(const SoilParams& p) : G_(p.shear_modulus), K_(p.bulk_modulus), rheology_(p.granular) {}

  const GranularRheology& rheology() const { return rheology_; }

  /// sqrt(J2) / P of a stress (the mobilised friction; 0 at zero stress): at most mu_2 for every stress the law
  /// returns, -.
  static Real friction_ratio(const Mat3& sigma) {
    const Real P = -sigma.trace() / 3;
    const Mat3 s = sigma + P * Mat3::Identity();
    const Real tau = std::sqrt(0.5 * s.squaredNorm());
    return P > 0 ? tau / P : (tau > 0 ? std::numeric_limits<Real>::infinity() : 0);
  }

  /// The equivalent plastic shear rate |gamma_dot_p| = sqrt(2 D_p : D_p) (1/s) of a step `dt` that relaxes the
  /// trial shear stress `tau_trial` = sqrt(J2*) > mu_s P at the pressure P > 0 (eq. 18.22): the positive root of
  ///   (tau* - mu_s P - G dt x)(I_0 + B x) = (mu_2 - mu_s) P B x,  B = d sqrt(rho_s / P),
  /// computed without cancellation.
  Real plastic_shear_rate(Real tau_trial, Real P, Real dt) const {
    const GranularRheology& r = rheology_;
    const Real excess = tau_trial - r.mu_s * P;
    const Real B = r.grain_diameter * std::sqrt(r.grain_density / P);
    const Real alpha = G_ * dt;
    const Real a = alpha * B;
    const Real b = alpha * r.I_0 + B * ((r.mu_2 - r.mu_s) * P - excess);
    const Real root = std::sqrt(b * b + 4 * a * excess * r.I_0);
    if (b >= 0) return 2 * excess * r.I_0 / (b + root);
    return (root - b) / (2 * a);  // b < 0 needs a > 0: with dt = 0 (a = 0) b = B (mu_2 P - tau*) < 0 has no root
  }

  /// The stress returned from the elastic trial stress (tension positive) over the step `dt`, Pa. `opening` is the
  /// volume strain by which the grains are apart at the start of the step (> 0: open, the stress was zero, so the
  /// trial is C : d eps of the step); the caller books the plastic volume strain C^-1 : (trial - sigma) into it
  /// (soil_batch.hpp, eq. 18.13), which makes it the opening at the end of the step.
  Mat3 return_map(const Mat3& trial, Real dt, Real opening = 0) const {
    Mat3 connected = trial;
    if (opening > 0) {
      // Open (eq. 18.23): the step's volume strain first closes the gap; what is left of the step after it has
      // closed loads the grains from zero stress.
      const Real dv = trial.trace() / (3 * K_);
      if (!(opening + dv < 0)) return Mat3::Zero();
      connected *= (opening + dv) / dv;
    }
    const Real P = -connected.trace() / 3;
    if (!(P > 0)) return Mat3::Zero();  // the grains lose contact (eq. 18.23)
    const Mat3 s = connected + P * Mat3::Identity();
    const Real tau = std::sqrt(0.5 * s.squaredNorm());
    if (tau <= rheology_.mu_s * P) return connected;  // at rest (eq. 18.21)
    Real relaxed = rheology_.mu_2 * P;                // the limit of an infinite rate (a step of zero length)
    if (dt > 0) {
      const Real rate = plastic_shear_rate(tau, P, dt);
      // On the root tau* - G dt rate = mu(I(rate)) P; the right-hand side has no cancellation (eq. 18.22).
      relaxed = P * rheology_.friction(rheology_.inertial_number(rate, P));
    }
    return std::min(relaxed, tau) / tau * s - P * Mat3::Identity();
  }

 private:
  Real G_, K_;
  GranularRheology rheology_;
};

}  // namespace mpm::soils
