#pragma once
/// \file elastoplastic.hpp
/// Hypoelastic-plastic-damage law with an equation of state (review App. B.3, Algs 11-13 with the digest's
/// errata 25-28), for one material point. Per step, with F and L at t + dt:
///   1. R from F = R U (polar_decomposition.hpp; in 3D warm-started from the last step's rotation);
///      un-rotated rate d = R^T sym(L) R, deviator d'. (Implemented in the current frame, see below.)
///   2. Radial return (Alg. 12, Leroch et al. 2016), flow stress held at eps_p^t:
///        G' = (1 - D) G,  s_trial = s' + 2 G' dt d',  sigma_eq = sqrt(3/2 s_trial : s_trial),
///        sigma_f = flow(eps_p, rate*, T*) (1 - D);  if sigma_eq > sigma_f:
///        d eps_p = (sigma_eq - sigma_f) / (3 G'),  s' = (sigma_f / sigma_eq) s_trial.   (D >= 1: s' = 0.)
///   3. Pressure p = EOS(J, e) with e = c rho0 (T - T_r) (eq. B.10), positive in compression; a tensile
///      pressure is scaled by (1 - D) (erratum 28: a failed point still resists compression). Optional
///      artificial bulk viscosity in compression, q = rho l (c_2 l (tr d)^2 - c_1 c_b tr d), l = V^(1/Dim).
///   4. sigma = R (s' - (p + q) 1) R^T   (the printed "+ p" of Alg. 11 is erratum 25).
///   5. Damage (Alg. 13, johnson_cook_damage.hpp) from d eps_p and the triaxiality -p / sigma_eq.
///   6. Adiabatic heating dT = chi sigma_f d eps_p / (rho c) (eq. B.13), when temperature is tracked.
/// rate* = max(eps_p_rate / rate0, 1) uses the plastic strain rate of the previous step (explicit, as the
/// flow stress), T* = (T - T_r)/(T_m - T_r) clamped to [0, 1].

#include <algorithm>
#include <cmath>

#include "mpm/plasticity/equation_of_state.hpp"
#include "mpm/plasticity/flow_stress.hpp"
#include "mpm/plasticity/johnson_cook_damage.hpp"
#include "mpm/plasticity/polar_decomposition.hpp"

namespace mpm::plasticity {

/// The rotation R_t of the last polar decomposition: the start of the next one in 3D, and the way to turn
/// the stored Cauchy deviator into the next step's frame (Delta R = R_{t+dt} R_t^T). 1D: R = 1.
template <int Dim>
struct RotationMemory {};
template <>
struct RotationMemory<2> {
  Real c = 1, s = 0;  ///< cos and sin of the rotation about z
};
template <>
struct RotationMemory<3> {
  Real q[4] = {1, 0, 0, 0};  ///< unit quaternion (w, x, y, z)
};

/// History of one material point (one on-demand particle field "plasticity", read and written together).
/// The deviatoric stress is not stored: s' = R^T dev(sigma) R, so the Cauchy stress and R_t carry it.
template <int Dim>
struct PlasticState {
  [[no_unique_address]] RotationMemory<Dim> rotation;  ///< R of F = R U at the last step
  Real plastic_strain = 0;                             ///< equivalent plastic strain eps_p, -
  Real plastic_strain_rate = 0;                        ///< d eps_p / dt over the last step, 1/s
  Real damage = 0;                                     ///< D in [0, 1]
  Real damage_initiation = 0;                          ///< D_init of eq. B.14
  Real plastic_work = 0;                               ///< dissipated energy per reference volume, J/m^3
  Real hardening = -1;  ///< cache of flow.hardening(plastic_strain), Pa (-1: not computed yet)
};

/// Constants shared by every flow law and equation of state.
struct PlasticityConstants {
  Real density = 0;                ///< rho0, kg/m^3
  Real shear_modulus = 0;          ///< G, Pa
  Real bulk_modulus = 0;           ///< K = E / (3 (1 - 2 nu)), Pa (lower bound of the wave-speed modulus)
  Real reference_strain_rate = 1;  ///< rate0, 1/s
  bool damage_enabled = false;
  JohnsonCookDamage damage;
  bool thermal = false;            ///< temperature tracked (field "temperature"), adiabatic heating
  Real specific_heat = 0;          ///< c, J/(kg K)
  Real taylor_quinney = 0.9;       ///< chi, -
  Real room_temperature = 293.15;  ///< T_r, K
  /// alpha, 1/K: the EOS sees the mechanical volume ratio J exp(-3 alpha (T - T_r)) (eq. 5.26; isotropic, so
  /// the deviatoric rate is unchanged). 0 = no thermal expansion.
  Real thermal_expansion = 0;
  bool softening = false;        ///< Johnson-Cook thermal softening (needs thermal)
  Real melting_temperature = 0;  ///< T_m, K
  Real viscosity_linear = 0;     ///< c_1, -
  Real viscosity_quadratic = 0;  ///< c_2, -
};

template <class Flow, class Eos>
struct ElastoplasticParams : PlasticityConstants {
  Flow flow;
  Eos eos;
};

template <class Flow, class Eos>
struct Elastoplastic {
  using Params = ElastoplasticParams<Flow, Eos>;

  /// One step of one point: F, L = velocity gradient and J = det F at t + dt, `volume` = current volume
  /// (for the artificial viscosity length). Reads and overwrites `state`, `*temperature` (K; nullptr when
  /// not tracked) and `stress` (Cauchy, Pa). To evaluate a trial deformation, call it on copies.
  template <int Dim>
  static inline void update_point(const Params& c, const Mat<Dim>& F, const Mat<Dim>& L, Real J, Real dt, Real volume,
                                  PlasticState<Dim>& state, Real* temperature, SymTensor<Dim>& stress) {
    // Alg. 11 in the current frame: with s' = R_t^T dev(sigma_t) R_t and d' = R^T dev(D) R (R = R_{t+dt}),
    // R (s' + 2 G dt d') R^T = Delta R dev(sigma_t) Delta R^T + 2 G dt dev(D), Delta R = R R_t^T; the radial
    // return only scales, so it commutes with the rotation. One rotation per step instead of three.
    Mat3 s = stress.full();
    const Real tr_s = s.trace();
    s.diagonal().array() -= tr_s / 3;
    if constexpr (Dim == 3) {
      const Real* q = state.rotation.q;
      const Real q0[4] = {q[0], -q[1], -q[2], -q[3]};  // R_t^T
      polar_update_warm(F, state.rotation.q);
      Real dq[4];  // q_{t+dt} (x) conj(q_t)
      dq[0] = q[0] * q0[0] - q[1] * q0[1] - q[2] * q0[2] - q[3] * q0[3];
      dq[1] = q[0] * q0[1] + q[1] * q0[0] + q[2] * q0[3] - q[3] * q0[2];
      dq[2] = q[0] * q0[2] - q[1] * q0[3] + q[2] * q0[0] + q[3] * q0[1];
      dq[3] = q[0] * q0[3] + q[1] * q0[2] - q[2] * q0[1] + q[3] * q0[0];
      s = rotate_symmetric(rotation_of(dq), s);
    } else if constexpr (Dim == 2) {
      const Real a = F(0, 0) + F(1, 1), b = F(1, 0) - F(0, 1), n = 1 / std::hypot(a, b);
      const Real c1 = a * n, s1 = b * n;
      const Real dc = c1 * state.rotation.c + s1 * state.rotation.s, ds = s1 * state.rotation.c - c1 * state.rotation.s;
      state.rotation.c = c1;
      state.rotation.s = s1;
      // rotate the in-plane block by [[dc, -ds], [ds, dc]]; zz is unchanged
      const Real xx = s(0, 0), yy = s(1, 1), xy = s(0, 1);
      s(0, 0) = dc * dc * xx - 2 * dc * ds * xy + ds * ds * yy;
      s(1, 1) = ds * ds * xx + 2 * dc * ds * xy + dc * dc * yy;
      s(0, 1) = s(1, 0) = dc * ds * (xx - yy) + (dc * dc - ds * ds) * xy;
    }
    Mat3 d;  // dev(D) in the current frame
    if constexpr (Dim == 1) {
      d = Mat3::Zero();
      d(0, 0) = L(0, 0);
    } else {
      const Mat3 L3 = embed<Dim>(L, 0);
      d = 0.5 * (L3 + L3.transpose());
    }
    const Real tr_d = d.trace();
    d.diagonal().array() -= tr_d / 3;

    const Real T = temperature ? *temperature : c.room_temperature;
    const Real T_star =
        c.softening
            ? std::clamp((T - c.room_temperature) / (c.melting_temperature - c.room_temperature), Real(0), Real(1))
            : Real(0);
    const Real D = state.damage;
    Real d_eps = 0, sigma_f = 0;
    if (D >= 1) {
      s.setZero();
    } else {
      const Real G = (1 - D) * c.shear_modulus;
      s += (2 * G * dt) * d;
      const Real eq = std::sqrt(1.5 * s.squaredNorm());
      const Real rate_star = std::max(state.plastic_strain_rate / c.reference_strain_rate, Real(1));
      if (state.hardening < 0) state.hardening = c.flow.hardening(state.plastic_strain);
      sigma_f = state.hardening * c.flow.factor(rate_star, T_star) * (1 - D);
      if (eq > sigma_f) {
        d_eps = (eq - sigma_f) / (3 * G);
        s *= sigma_f / eq;
      }
    }

    const Real e = c.thermal ? c.specific_heat * c.density * (T - c.room_temperature) : Real(0);
    const Real J_mech =
        c.thermal_expansion != 0 ? J * std::exp(-3 * c.thermal_expansion * (T - c.room_temperature)) : J;
    Real p = c.eos.pressure(J_mech, e);
    if (p < 0) p *= 1 - D;
    Real q = 0;
    if (tr_d < 0 && (c.viscosity_linear > 0 || c.viscosity_quadratic > 0)) {
      const Real rho = c.density / J, l = std::pow(volume, Real(1) / Dim);
      const Real cb = std::sqrt(std::max(c.bulk_modulus, c.eos.tangent_bulk_modulus(J)) / rho);
      q = rho * l * (c.viscosity_quadratic * l * tr_d * tr_d - c.viscosity_linear * cb * tr_d);
    }
    Mat3 sigma = s;
    sigma.diagonal().array() -= p + q;
    stress = SymTensor<Dim>::from(sigma);

    if (d_eps > 0) {
      if (c.damage_enabled) {
        const Real eq = std::sqrt(1.5 * s.squaredNorm());
        const Real triaxiality = eq > 0 ? -p / eq : Real(0);
        const Real rate_star = std::max(d_eps / (dt * c.reference_strain_rate), Real(1));
        state.damage_initiation += d_eps / c.damage.failure_strain(triaxiality, rate_star, T_star);
        state.damage = c.damage.damage(state.damage_initiation);
      }
      if (temperature) *temperature += c.taylor_quinney * sigma_f * d_eps * J / (c.density * c.specific_heat);
      state.plastic_work += J * sigma_f * d_eps;
    }
    if (d_eps > 0) {
      state.plastic_strain += d_eps;
      state.hardening = c.flow.hardening(state.plastic_strain);  // for the next step (one power law per plastic step)
    }
    state.plastic_strain_rate = d_eps / dt;
  }

  /// Dilatational wave speed sqrt((K_t + 4 G / 3) / rho), rho = rho0 / J, K_t the larger of K and the
  /// EOS tangent modulus (damage ignored: conservative).
  static inline Real wave_speed_squared(const Params& c, Real J) {
    const Real K = std::max(c.bulk_modulus, c.eos.tangent_bulk_modulus(J));
    return (K + 4 * c.shear_modulus / 3) * std::max(J, Real(0)) / c.density;
  }
  static inline Real wave_speed(const Params& c, Real J) { return std::sqrt(wave_speed_squared(c, J)); }

  /// Stored elastic energy per reference volume: J dev(sigma):dev(sigma) / (4 G) + W_eos(J).
  static inline Real energy_density(const Params& c, Real J, const Mat3& stress) {
    const Mat3 dev = stress - stress.trace() / 3 * Mat3::Identity();
    return J * dev.squaredNorm() / (4 * c.shear_modulus) + c.eos.energy(J);
  }
};

}  // namespace mpm::plasticity
