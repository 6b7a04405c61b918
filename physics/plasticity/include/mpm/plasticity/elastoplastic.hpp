#pragma once
/// \file elastoplastic.hpp
/// Hypoelastic-plastic-damage law with an equation of state (review App. B.3, Algs 11-13 with the errata
/// docs/errata.md #25-28), for one material point. Per step, with F and L at t + dt:
///   1. R from F = R U (polar_decomposition.hpp; in 3D warm-started from the last step's rotation);
///      un-rotated rate d = R^T sym(L) R, deviator d'. (Implemented in the current frame, see below.)
///   2. Radial return (Alg. 12, Leroch et al. 2016), flow stress held at eps_p^t:
///        G' = (1 - D) G,  s_trial = s' + 2 G' dt d',  sigma_eq = sqrt(3/2 s_trial : s_trial),
///        sigma_f = flow(eps_p, rate*, T*) (1 - D);  if sigma_eq > sigma_f:
///        d eps_p = (sigma_eq - sigma_f) / (3 G'),  s' = (sigma_f / sigma_eq) s_trial.   (D >= 1: s' = 0.)
///   3. Pressure p = EOS(J, e) with e = c rho0 (T - T_r) (eq. B.10), positive in compression; a tensile
///      pressure is scaled by (1 - D) (docs/errata.md #28: a failed point still resists compression). Optional
///      artificial bulk viscosity in compression, q = rho l (c_2 l (tr d)^2 - c_1 c_b tr d), l = V^(1/Dim).
///   4. sigma = R (s' - (p + q) 1) R^T   (the printed "+ p" of Alg. 11 is docs/errata.md #25).
///   5. Damage (Alg. 13, johnson_cook_damage.hpp) from d eps_p and the triaxiality -p / sigma_eq.
///   6. Adiabatic heating dT = chi sigma_f d eps_p / (rho c) (eq. B.13), when temperature is tracked.
/// rate* = max(eps_p_rate / rate0, 1) uses the plastic strain rate of the previous step (explicit, as the
/// flow stress), T* = (T - T_r)/(T_m - T_r) clamped to [0, 1].
/// The law is written once for one point (Real) and for lane_count points side by side (Pack, lanes.hpp):
/// update_point is the scalar entry, update<Dim, Pack> the one the batched material runs on whole packs.

#include <algorithm>
#include <cmath>

#include "mpm/plasticity/equation_of_state.hpp"
#include "mpm/plasticity/flow_stress.hpp"
#include "mpm/plasticity/johnson_cook_damage.hpp"
#include "mpm/plasticity/lanes.hpp"
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

/// History of one material point (one on-demand particle field, keys::plastic_state, read and written together).
/// The deviatoric stress is not stored: s' = R^T dev(sigma) R, so the Cauchy stress and R_t carry it.
template <int Dim>
struct PlasticState {
  using scalar_type = Real;  ///< a struct of Reals: checkpointed as an array of doubles (field_layout.hpp)
  [[no_unique_address]] RotationMemory<Dim> rotation;  ///< R of F = R U at the last step
  Real plastic_strain = 0;                             ///< equivalent plastic strain eps_p, -
  Real plastic_strain_rate = 0;                        ///< d eps_p / dt over the last step, 1/s
  Real damage = 0;                                     ///< D in [0, 1]
  Real damage_initiation = 0;                          ///< D_init of eq. B.14
  Real plastic_work = 0;                               ///< dissipated energy per reference volume, J/m^3
  Real hardening = -1;  ///< cache of flow.hardening(plastic_strain), Pa (-1: not computed yet)
};

/// v <- x (T = Real), or lane l of v <- x (T = Pack).
inline void set_lane(Real& v, int, Real x) { v = x; }
inline void set_lane(Pack& v, int l, Real x) { v[l] = x; }

/// What the point law reads and writes, for one point (T = Real) or lane_count points (T = Pack): the
/// kinematics at t + dt, the history of PlasticState, the temperature and the Cauchy stress (SymTensor
/// layout). q is R_t as a quaternion in 3D, (cos, sin) of its angle in 2D, unused in 1D.
template <int Dim, class T>
struct PointLanes {
  T F[Dim][Dim], L[Dim][Dim];
  T L_hoop;     ///< 2D: the out-of-plane rate, 0 in plane strain and L_tt = v_r / r on an axisymmetric body
  T J, volume;  ///< volume: the particle's size for the viscosity length (its meridian area when axisymmetric)
  T q[4];
  T plastic_strain, plastic_strain_rate, damage, damage_initiation, plastic_work, hardening;
  T temperature;
  T stress[SymTensor<Dim>::size];

  /// This point's history (T = Real), or lane l's (T = Pack), from `st`.
  void load_state(const PlasticState<Dim>& st, int l) {
    if constexpr (Dim == 3)
      for (int k = 0; k < 4; ++k) set_lane(q[k], l, st.rotation.q[k]);
    if constexpr (Dim == 2) {
      set_lane(q[0], l, st.rotation.c);
      set_lane(q[1], l, st.rotation.s);
    }
    set_lane(plastic_strain, l, st.plastic_strain);
    set_lane(plastic_strain_rate, l, st.plastic_strain_rate);
    set_lane(damage, l, st.damage);
    set_lane(damage_initiation, l, st.damage_initiation);
    set_lane(plastic_work, l, st.plastic_work);
    set_lane(hardening, l, st.hardening);
  }
  void store_state(PlasticState<Dim>& st, int l) const {
    if constexpr (Dim == 3)
      for (int k = 0; k < 4; ++k) st.rotation.q[k] = lanes::lane(q[k], l);
    if constexpr (Dim == 2) {
      st.rotation.c = lanes::lane(q[0], l);
      st.rotation.s = lanes::lane(q[1], l);
    }
    st.plastic_strain = lanes::lane(plastic_strain, l);
    st.plastic_strain_rate = lanes::lane(plastic_strain_rate, l);
    st.damage = lanes::lane(damage, l);
    st.damage_initiation = lanes::lane(damage_initiation, l);
    st.plastic_work = lanes::lane(plastic_work, l);
    st.hardening = lanes::lane(hardening, l);
  }
};

/// s : s for a symmetric s stored as (xx, yy, zz, xy, yz, xz).
template <class T>
inline T squared_norm(const T s[6]) {
  return s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
}

/// Constants shared by every flow law and equation of state.
struct PlasticityConstants {
  Real density = 0;                ///< rho0, kg/m^3
  Real shear_modulus = 0;          ///< G, Pa
  Real bulk_modulus = 0;           ///< K = E / (3 (1 - 2 nu)), Pa (lower bound of the wave-speed modulus)
  Real reference_strain_rate = 1;  ///< rate0, 1/s
  bool damage_enabled = false;
  JohnsonCookDamage damage;
  bool thermal = false;            ///< temperature tracked (field keys::temperature), adiabatic heating
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
  /// (for the artificial viscosity length; the meridian area of an axisymmetric particle). Reads and overwrites
  /// `state`, `*temperature` (K; nullptr when not tracked) and `stress` (Cauchy, Pa). `hoop_rate`: L_tt of an
  /// axisymmetric particle (2D; J then includes F_tt). To evaluate a trial deformation, call it on copies.
  template <int Dim>
  static inline void update_point(const Params& c, const Mat<Dim>& F, const Mat<Dim>& L, Real J, Real dt, Real volume,
                                  PlasticState<Dim>& state, Real* temperature, SymTensor<Dim>& stress,
                                  Real hoop_rate = 0) {
    PointLanes<Dim, Real> p;
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j) {
        p.F[i][j] = F(i, j);
        p.L[i][j] = L(i, j);
      }
    p.L_hoop = hoop_rate;
    p.J = J;
    p.volume = volume;
    p.load_state(state, 0);
    p.temperature = temperature ? *temperature : c.room_temperature;
    for (int k = 0; k < SymTensor<Dim>::size; ++k) p.stress[k] = stress.c[k];
    update<Dim>(c, dt, temperature != nullptr, p);
    p.store_state(state, 0);
    if (temperature) *temperature = p.temperature;
    for (int k = 0; k < SymTensor<Dim>::size; ++k) stress.c[k] = p.stress[k];
  }

  /// The step of update_point for one point (T = Real) or lane_count points at once (T = Pack): every
  /// branch of the law is a mask and a select (lanes.hpp), so both widths run the same arithmetic.
  /// `track_temperature`: p.temperature is read (softening, EOS energy, expansion) and heated.
  /// The steps of the file comment, in order (each helper is inlined: the arithmetic is that of one function).
  template <int Dim, class T>
  static inline void update(const Params& c, Real dt, bool track_temperature, PointLanes<Dim, T>& p) {
    T s[6], d[6];
    rotated_deviator(p, s);                // step 1: s = Delta R dev(sigma_t) Delta R^T
    const T tr_d = deviatoric_rate(p, d);  // step 1: d = dev(D)
    const T T_now = track_temperature ? p.temperature : lanes::splat<T>(c.room_temperature);
    const T T_star = homologous_temperature(c, T_now);
    const PlasticFlow<T> flow = radial_return(c, dt, T_star, d, p, s);  // step 2
    const T pressure = eos_pressure(c, T_now, p);                       // step 3
    const T q_visc = artificial_viscosity(c, tr_d, p);
    assemble_stress(s, T(pressure + q_visc), p);                             // step 4
    update_history(c, dt, track_temperature, s, pressure, T_star, flow, p);  // steps 5-6
  }

  /// What the radial return leaves for the history update: the flow stress sigma_f (Pa, 0 for a failed
  /// point) and the plastic strain increment d eps_p of the step.
  template <class T>
  struct PlasticFlow {
    T sigma_f;
    T d_eps;
  };

  /// Step 1, stress: s = dev(sigma_t) as (xx, yy, zz, xy, yz, xz), turned by Delta R = R_{t+dt} R_t^T; p.q
  /// becomes R_{t+dt}. Alg. 11 in the current frame: with s' = R_t^T dev(sigma_t) R_t and d' = R^T dev(D) R
  /// (R = R_{t+dt}), R (s' + 2 G dt d') R^T = Delta R dev(sigma_t) Delta R^T + 2 G dt dev(D); the radial
  /// return only scales, so it commutes with the rotation. One rotation per step instead of three.
  template <int Dim, class T>
  static inline void rotated_deviator(PointLanes<Dim, T>& p, T s[6]) {
    s[0] = p.stress[0];
    s[1] = p.stress[1];
    s[2] = p.stress[2];
    s[3] = s[4] = s[5] = lanes::splat<T>(0);
    if constexpr (Dim >= 2) s[3] = p.stress[3];
    if constexpr (Dim == 3) {
      s[4] = p.stress[4];
      s[5] = p.stress[5];
    }
    {
      const T mean = (s[0] + s[1] + s[2]) * (Real(1) / 3);
      for (int k = 0; k < 3; ++k) s[k] = s[k] - mean;
    }
    if constexpr (Dim == 3) {
      const T q0[4] = {p.q[0], T(-p.q[1]), T(-p.q[2]), T(-p.q[3])};  // R_t^T
      polar_update_warm(p.F, p.q);
      const T* q = p.q;
      const T dq[4] = {q[0] * q0[0] - q[1] * q0[1] - q[2] * q0[2] - q[3] * q0[3],  // q_{t+dt} (x) conj(q_t)
                       q[0] * q0[1] + q[1] * q0[0] + q[2] * q0[3] - q[3] * q0[2],
                       q[0] * q0[2] - q[1] * q0[3] + q[2] * q0[0] + q[3] * q0[1],
                       q[0] * q0[3] + q[1] * q0[2] - q[2] * q0[1] + q[3] * q0[0]};
      T dR[3][3];
      rotation_matrix(dq, dR);
      rotate_symmetric(dR, s);
    } else if constexpr (Dim == 2) {
      // R about z by atan2(F_yx - F_xy, F_xx + F_yy); p.q = (cos, sin) of R_t
      const T a = p.F[0][0] + p.F[1][1], b = p.F[1][0] - p.F[0][1];
      const T n = 1 / lanes::hypot(a, b);
      const T c1 = a * n, s1 = b * n;
      const T dc = c1 * p.q[0] + s1 * p.q[1], ds = s1 * p.q[0] - c1 * p.q[1];
      p.q[0] = c1;
      p.q[1] = s1;
      // rotate the in-plane block by [[dc, -ds], [ds, dc]]; zz is unchanged
      const T xx = s[0], yy = s[1], xy = s[3];
      s[0] = dc * dc * xx - 2 * dc * ds * xy + ds * ds * yy;
      s[1] = ds * ds * xx + 2 * dc * ds * xy + dc * dc * yy;
      s[3] = dc * ds * (xx - yy) + (dc * dc - ds * ds) * xy;
    }
  }

  /// Step 1, rate: d = dev(D), D = sym(L) (with L_tt out of plane in 2D), in the current frame; returns tr D.
  template <int Dim, class T>
  static inline T deviatoric_rate(const PointLanes<Dim, T>& p, T d[6]) {
    d[0] = p.L[0][0];
    d[1] = d[2] = d[3] = d[4] = d[5] = lanes::splat<T>(0);
    if constexpr (Dim >= 2) {
      d[1] = p.L[1][1];
      d[3] = 0.5 * (p.L[0][1] + p.L[1][0]);
    }
    if constexpr (Dim == 2) d[2] = p.L_hoop;
    if constexpr (Dim == 3) {
      d[2] = p.L[2][2];
      d[4] = 0.5 * (p.L[1][2] + p.L[2][1]);
      d[5] = 0.5 * (p.L[0][2] + p.L[2][0]);
    }
    const T tr_d = d[0] + d[1] + d[2];
    const T mean = tr_d * (Real(1) / 3);
    for (int k = 0; k < 3; ++k) d[k] = d[k] - mean;
    return tr_d;
  }

  /// T* = (T - T_r) / (T_m - T_r) clamped to [0, 1] with softening, else 0.
  template <class T>
  static inline T homologous_temperature(const Params& c, const T& T_now) {
    return c.softening ? lanes::clamp(T((T_now - c.room_temperature) / (c.melting_temperature - c.room_temperature)),
                                      Real(0), Real(1))
                       : lanes::splat<T>(0);
  }

  /// Step 2, the radial return (Alg. 12) on s with the flow stress at eps_p^t; a failed point (D >= 1) keeps
  /// no deviatoric stress and does not flow. Fills the hardening cache when it is empty.
  template <int Dim, class T>
  static inline PlasticFlow<T> radial_return(const Params& c, Real dt, const T& T_star, const T d[6],
                                             PointLanes<Dim, T>& p, T s[6]) {
    using Mask = MaskOf<T>;
    const T D = p.damage;
    const Mask broken = D >= 1;
    const T G = (1 - D) * c.shear_modulus;
    {
      const T g2dt = 2 * dt * G;
      for (int k = 0; k < 6; ++k) s[k] = s[k] + g2dt * d[k];
    }
    const T eq = lanes::sqrt(T(1.5 * squared_norm(s)));
    const T rate_star = lanes::max(T(p.plastic_strain_rate / c.reference_strain_rate), Real(1));
    const Mask uncached = p.hardening < 0;
    if (lanes::any(uncached)) p.hardening = lanes::select(uncached, c.flow.hardening(p.plastic_strain), p.hardening);
    const T flow = p.hardening * c.flow.factor(rate_star, T_star) * (1 - D);
    const T sigma_f = lanes::select(broken, Real(0), flow);
    const Mask yielding = lanes::both(eq > sigma_f, lanes::negate(broken));
    const T d_eps = lanes::select(yielding, T((eq - sigma_f) / (3 * G)), Real(0));
    {
      const T to_surface = sigma_f / eq;
      const T scale = lanes::select(broken, Real(0), lanes::select(yielding, to_surface, Real(1)));
      for (int k = 0; k < 6; ++k) s[k] = s[k] * scale;
    }
    return {sigma_f, d_eps};
  }

  /// Step 3, pressure (eq. B.10, positive in compression) of the mechanical volume ratio (thermal expansion,
  /// eq. 5.26) and the energy c rho0 (T - T_r); a tensile pressure is scaled by (1 - D) (docs/errata.md #28).
  template <int Dim, class T>
  static inline T eos_pressure(const Params& c, const T& T_now, const PointLanes<Dim, T>& p) {
    const T J = p.J;
    const T e = c.thermal ? T(c.specific_heat * c.density * (T_now - c.room_temperature)) : lanes::splat<T>(0);
    T J_mech = J;
    if (c.thermal_expansion != 0) {
      const T expansion = lanes::exp(T(-3 * c.thermal_expansion * (T_now - c.room_temperature)));
      J_mech = J * expansion;
    }
    T pressure = c.eos.pressure(J_mech, e);
    pressure = lanes::select(pressure < 0, T(pressure * (1 - p.damage)), pressure);
    return pressure;
  }

  /// Step 3, artificial bulk viscosity in compression, q = rho l (c_2 l (tr d)^2 - c_1 c_b tr d), l = V^(1/Dim).
  template <int Dim, class T>
  static inline T artificial_viscosity(const Params& c, const T& tr_d, const PointLanes<Dim, T>& p) {
    using Mask = MaskOf<T>;
    T q_visc = lanes::splat<T>(0);
    if (c.viscosity_linear > 0 || c.viscosity_quadratic > 0) {
      const Mask compressing = tr_d < 0;
      if (lanes::any(compressing)) {
        const T J = p.J;
        const T rho = c.density / J;
        const T l = lanes::power(p.volume, Real(1) / Dim);
        const T cb = lanes::sqrt(T(lanes::max(c.eos.tangent_bulk_modulus(J), c.bulk_modulus) / rho));
        const T q = rho * l * (c.viscosity_quadratic * l * tr_d * tr_d - c.viscosity_linear * cb * tr_d);
        q_visc = lanes::select(compressing, q, Real(0));
      }
    }
    return q_visc;
  }

  /// Step 4, sigma = s' - (p + q) 1 (the printed "+ p" of Alg. 11 is docs/errata.md #25), in the SymTensor layout.
  template <int Dim, class T>
  static inline void assemble_stress(const T s[6], const T& total_pressure, PointLanes<Dim, T>& p) {
    p.stress[0] = s[0] - total_pressure;
    p.stress[1] = s[1] - total_pressure;
    p.stress[2] = s[2] - total_pressure;
    if constexpr (Dim >= 2) p.stress[3] = s[3];
    if constexpr (Dim == 3) {
      p.stress[4] = s[4];
      p.stress[5] = s[5];
    }
  }

  /// Steps 5-6: damage (Alg. 13) from d eps_p and the triaxiality -p / sigma_eq, adiabatic heating (eq. B.13),
  /// dissipated work, plastic strain and its rate; d eps_p = 0 leaves the history unchanged.
  template <int Dim, class T>
  static inline void update_history(const Params& c, Real dt, bool track_temperature, const T s[6], const T& pressure,
                                    const T& T_star, const PlasticFlow<T>& flow, PointLanes<Dim, T>& p) {
    using Mask = MaskOf<T>;
    const T& d_eps = flow.d_eps;
    const Mask flowing = d_eps > 0;
    if (lanes::any(flowing)) {
      if (c.damage_enabled) {
        const T eq_after = lanes::sqrt(T(1.5 * squared_norm(s)));
        const T triaxiality = lanes::select(eq_after > 0, T(-pressure / eq_after), Real(0));
        const T d_rate_star = lanes::max(T(d_eps / (dt * c.reference_strain_rate)), Real(1));
        const T initiation = p.damage_initiation + d_eps / c.damage.failure_strain(triaxiality, d_rate_star, T_star);
        p.damage_initiation = lanes::select(flowing, initiation, p.damage_initiation);
        p.damage = lanes::select(flowing, c.damage.damage(p.damage_initiation), p.damage);
      }
      const T work = p.J * flow.sigma_f * d_eps;
      if (track_temperature) p.temperature = p.temperature + (c.taylor_quinney / (c.density * c.specific_heat)) * work;
      p.plastic_work = p.plastic_work + work;
      p.plastic_strain = p.plastic_strain + d_eps;
      // for the next step (one power law per plastic step)
      p.hardening = lanes::select(flowing, c.flow.hardening(p.plastic_strain), p.hardening);
    }
    p.plastic_strain_rate = d_eps * (1 / dt);
  }

  /// Dilatational wave speed sqrt((K_t + 4 G / 3) / rho), rho = rho0 / J, K_t the larger of K and the
  /// EOS tangent modulus (damage ignored: conservative).
  template <class T>
  static inline T wave_speed_squared(const Params& c, const T& J) {
    const T K = lanes::max(c.eos.tangent_bulk_modulus(J), c.bulk_modulus);
    return (K + 4 * c.shear_modulus / 3) * lanes::max(J, Real(0)) * (1 / c.density);
  }
  static inline Real wave_speed(const Params& c, Real J) { return std::sqrt(wave_speed_squared(c, J)); }

  /// The wave speed squared of a point with damage D: the dilatational one above while D < 1; a failed point
  /// (D >= 1) carries only compressive pressure (eq. 16.2), so its speed is the bulk one of that response,
  /// K_t(J') J' / rho0 with J' = min(J, 1) (eq. 16.5): no shear, and an expanded failed point, which carries no
  /// tension, is bounded as one at rest rather than by the growing J of its expansion.
  template <class T>
  static inline T wave_speed_squared(const Params& c, const T& J, const T& D) {
    const T J1 = lanes::min(J, lanes::splat<T>(1));
    const T failed =
        lanes::max(c.eos.tangent_bulk_modulus(J1), c.bulk_modulus) * lanes::max(J1, Real(0)) * (1 / c.density);
    const MaskOf<T> broken = D >= 1;
    return lanes::select(broken, failed, wave_speed_squared(c, J));
  }
  static inline Real wave_speed(const Params& c, Real J, Real D) { return std::sqrt(wave_speed_squared(c, J, D)); }

  /// Stored elastic energy per reference volume: J dev(sigma):dev(sigma) / (4 G) + W_eos(J).
  static inline Real energy_density(const Params& c, Real J, const Mat3& stress) {
    const Mat3 dev = stress - stress.trace() / 3 * Mat3::Identity();
    return J * dev.squaredNorm() / (4 * c.shear_modulus) + c.eos.energy(J);
  }
};

}  // namespace mpm::plasticity
