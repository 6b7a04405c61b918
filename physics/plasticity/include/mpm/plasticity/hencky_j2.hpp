#pragma once
/// \file hencky_j2.hpp
/// Finite-strain J2 (visco)plasticity with Hencky elasticity, multiplicative, on the elastic left Cauchy-Green
/// tensor b^e (Love & Sulsky, ref. 003 §2.3.2 and §3.2; equation numbers are the paper's; docs/implicit.md).
/// One material point, one step, as a PURE function of the state at t_n and the deformation gradient at
/// t_{n+1} (an implicit scheme calls it for every trial deformation of a Newton iteration), and a separate
/// commit that makes the result the particle's state:
///   1. trial (eqs. 54, 21):  b^e_tr = F_{n+1} G^p_n F_{n+1}^T  (= f b^e_n f^T with f = F_{n+1} F_n^-1, eq. 91);
///   2. principal logarithmic strains eps_A^tr = ln lambda_A^tr (eqs. 64, 70), lambda_A^tr^2 the eigenvalues of
///      b^e_tr; deviatoric Kirchhoff stress beta^tr = 2 G dev eps^tr (eq. 44);
///   3. yield function (37) Phi^tr = ||beta^tr|| - sqrt(2/3) (sigma_Y - q_n), q = -H xi (eq. 45);
///   4. Phi^tr > 0: Delta gamma = Phi^tr / (eta/dt + 2H/3 + 2G) (eq. 73), return along n = beta^tr/||beta^tr||
///      (eqs. 38, 71): eps = eps^tr - Delta gamma n, xi += sqrt(2/3) Delta gamma (eq. 62),
///      Delta D = (eta/dt Delta gamma + sqrt(2/3) sigma_Y) Delta gamma (eq. 74);
///   5. b^e_{n+1} = sum exp(2 eps_A) m_A m_A (eq. 65, m_A those of b^e_tr, eq. 70), G^p_{n+1} = F^-1 b^e F^-T,
///      dev tau = sum 2 G (dev eps)_A m_A m_A (eq. 66), W~ = G ||dev eps||^2 + H xi^2 / 2 (eqs. 44, 45).
/// The state keeps the inverse plastic metric G^p = (F^pT F^p)^-1 (eq. 20) instead of b^e: the trial state
/// then needs only F_{n+1}, whichever way a scheme forms it (USL/MUSL/USF: (1 + dt L) F_n; TLMPM: F_n +
/// dt Fdot), and b^e = F G^p F^T (eq. 21) is one product away. The volumetric part (U(Theta), pressure) is
/// not in this function: log_volumetric_energy.hpp.

#include <cmath>
#include <numbers>

#include "mpm/core/types.hpp"
#include "mpm/plasticity/symmetric_eigen.hpp"

namespace mpm::plasticity {

/// Constants of hencky_j2 (scene keys in physics/plasticity/README.md).
struct HenckyJ2Params {
  Real density = 0;            ///< rho_0, kg/m^3
  Real bulk_modulus = 0;       ///< K of U = K/2 ln^2 Theta, Pa
  Real shear_modulus = 0;      ///< G, Pa
  bool plastic = false;        ///< false: Hencky elasticity only (no yield_stress given)
  Real yield_stress = 0;       ///< sigma_Y, Pa
  Real hardening_modulus = 0;  ///< H of the linear hardening q = -H xi (eq. 45), Pa
  Real viscosity = 0;          ///< eta of the viscoplastic regularisation (eq. 35), Pa s (0: rate independent)
};

/// History of one material point. Dim fixes which components of G^p can be non-zero (types.hpp).
template <int Dim>
struct HenckyJ2State {
  using scalar_type = Real;  ///< a struct of Reals: checkpointed as an array of doubles (field_layout.hpp)
  SymTensor<Dim> plastic_metric = SymTensor<Dim>::from(Mat3::Identity());  ///< G^p (eq. 20), 1 when virgin
  Real xi = 0;            ///< hardening variable xi, the equivalent plastic strain (after eq. 42)
  Real plastic_work = 0;  ///< the sum of Delta D over the committed steps, J/m^3 of reference volume
};

/// What one evaluation returns: the state at t_{n+1} for this deformation (not committed) and the
/// quantities the implicit scheme needs for the algorithmic stress (eqs. 81-83).
template <int Dim>
struct HenckyJ2Update {
  HenckyJ2State<Dim> state;        ///< G^p_{n+1}, xi_{n+1}, plastic work + Delta D
  Mat3 dev_kirchhoff;              ///< dev tau_{n+1}, Pa
  Mat3 elastic_left_cauchy_green;  ///< b^e_{n+1}
  Real stored_energy = 0;          ///< W~(b^e_{n+1}, xi_{n+1}) (eq. 44), J/m^3 of reference volume
  Real dissipation = 0;            ///< Delta D (eq. 74), J/m^3 of reference volume (0 in an elastic step)
  Real delta_gamma = 0;            ///< Delta gamma (eq. 73), 0 in an elastic step
  Real yield_function = 0;         ///< Phi_{n+1} (eq. 37), Pa: <= 0 elastic, = eta Delta gamma / dt plastic
};

/// The point law (static functions, so a batch loop inlines them).
struct HenckyJ2 {
  /// sqrt(2/3)
  static constexpr Real root_two_thirds = 0.81649658092772603273;

  /// The step t_n -> t_{n+1}: `state_n` and the deformation gradient F (3x3; plane strain F_zz = 1,
  /// axisymmetric F_zz = r/R) at t_{n+1}, over dt (s; used only when viscosity > 0). Pure: nothing is
  /// written; commit() the result once the step is accepted.
  template <int Dim>
  static HenckyJ2Update<Dim> evaluate(const HenckyJ2Params& c, const HenckyJ2State<Dim>& state_n, const Mat3& F,
                                      Real dt) {
    return respond<Dim>(c, state_n, F, dt, c.plastic);
  }

  /// The elastic response at F with the plastic state held (no return mapping): dev tau and W~ of a committed
  /// state, e.g. at t_n for the algorithmic stress (eq. 82). yield_function is Phi there.
  template <int Dim>
  static HenckyJ2Update<Dim> elastic_response(const HenckyJ2Params& c, const HenckyJ2State<Dim>& state, const Mat3& F) {
    return respond<Dim>(c, state, F, 0, false);
  }

  /// Makes an accepted evaluation the point's state.
  template <int Dim>
  static void commit(HenckyJ2State<Dim>& state, const HenckyJ2Update<Dim>& u) {
    state = u.state;
  }

 private:
  /// Steps 1-5 of the file comment; the return (step 4) only when `return_map` and Phi^tr > 0.
  template <int Dim>
  static HenckyJ2Update<Dim> respond(const HenckyJ2Params& c, const HenckyJ2State<Dim>& state_n, const Mat3& F, Real dt,
                                     bool return_map) {
    const Mat3 Gp = state_n.plastic_metric.full();
    Mat3 b_trial = F * Gp * F.transpose();
    b_trial = (0.5 * (b_trial + b_trial.transpose())).eval();
    const SymmetricEigen e = symmetric_eigen<Dim>(b_trial);
    const Vec3 eps_trial = 0.5 * e.values.array().log();  // ln lambda_A^tr (eq. 70)
    const Real volumetric = eps_trial.sum() / 3;
    Vec3 dev_eps = (eps_trial.array() - volumetric).matrix();
    const Real G = c.shear_modulus, H = c.hardening_modulus;
    const Real norm_trial = 2 * G * dev_eps.norm();  // ||dev tau^tr||

    HenckyJ2Update<Dim> u;
    u.state = state_n;
    u.yield_function = c.plastic ? norm_trial - root_two_thirds * (c.yield_stress + H * state_n.xi) : 0;  // eq. 37
    if (return_map && u.yield_function > 0) {
      const Real eta_dt = c.viscosity > 0 ? c.viscosity / dt : 0;
      const Real dgamma = u.yield_function / (eta_dt + 2 * H / 3 + 2 * G);  // eq. 73
      dev_eps *= 1 - 2 * G * dgamma / norm_trial;                           // eps = eps^tr - dgamma n (eqs. 38, 71)
      u.delta_gamma = dgamma;
      u.state.xi = state_n.xi + root_two_thirds * dgamma;                             // eq. 62
      u.dissipation = (eta_dt * dgamma + root_two_thirds * c.yield_stress) * dgamma;  // eq. 74
      u.state.plastic_work = state_n.plastic_work + u.dissipation;
      u.yield_function = 2 * G * dev_eps.norm() - root_two_thirds * (c.yield_stress + H * u.state.xi);
      const Vec3 eps = (dev_eps.array() + volumetric).matrix();
      u.elastic_left_cauchy_green = spectral_sum(e, (2 * eps).array().exp().matrix());  // eq. 65
      const Mat3 F_inv = F.inverse();
      u.state.plastic_metric = SymTensor<Dim>::from(F_inv * u.elastic_left_cauchy_green * F_inv.transpose());
    } else {
      u.elastic_left_cauchy_green = b_trial;  // G^p and xi unchanged (eq. 54)
    }
    u.dev_kirchhoff = spectral_sum(e, 2 * G * dev_eps);  // eq. 66 with beta = 2 G dev eps (eq. 44)
    u.stored_energy = G * dev_eps.squaredNorm() + 0.5 * H * u.state.xi * u.state.xi;
    return u;
  }
};

}  // namespace mpm::plasticity
