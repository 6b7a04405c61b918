#pragma once
/// \file hencky_j2_batch.hpp
/// hencky_j2 (hencky_j2.hpp) as an ordinary material of the explicit schemes (USL, MUSL, USF, TLMPM): one
/// virtual call per block, the point law inlined, the history in one on-demand particle field
/// (keys::hencky_j2_state: HenckyJ2State, G^p, xi, plastic work). The volumetric part is U(J)
/// (log_volumetric_energy.hpp with Theta = J), so the Kirchhoff stress is tau = dev tau + K ln(J) 1 and the Cauchy
/// stress sigma = tau / J (eq. 3). Each step commits its evaluation at once (the explicit schemes have no trial
/// deformations). Outputs: plastic_strain (xi); energy audit: strain energy W~ + U(J), plastic work sum Delta D.

#include <algorithm>
#include <cmath>
#include <string_view>

#include "mpm/materials/material.hpp"
#include "mpm/plasticity/field_keys.hpp"
#include "mpm/plasticity/hencky_j2.hpp"
#include "mpm/plasticity/log_volumetric_energy.hpp"
#include "mpm/schemes/axisymmetric.hpp"

namespace mpm::plasticity {

template <int Dim>
class HenckyJ2Batch final : public Material<Dim> {
 public:
  using State = HenckyJ2State<Dim>;
  static constexpr const char* key = "hencky_j2";
  static constexpr FieldKey<State> state_field = keys::hencky_j2_state<Dim>;

  explicit HenckyJ2Batch(const HenckyJ2Params& params) : params_(params), volumetric_{params.bulk_modulus} {}
  std::string_view model() const override { return key; }
  Real density() const override { return params_.density; }
  const HenckyJ2Params& params() const { return params_; }

  void prepare_particles(ParticleSet<Dim>& p) const override { p.add_field(state_field, State{}); }

  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>*, Real dt) override {
    State* state = p.field(state_field).data();
    const Real* hoop = axisym::hoop_stretch_of(p);  // axisymmetric: F_tt out of plane
    Real sum = 0;                                   // finite stresses have a finite sum
    Vec<Dim> max_speed = Vec<Dim>::Zero();          // max (|v_a| + c) per particle: the same for any cut into blocks
    for (Index i = begin; i != end; ++i) {
      const Mat3 F = axisym::deformation_gradient_3x3(p, i, hoop);
      const Real J = F.determinant();
      const HenckyJ2Update<Dim> u = HenckyJ2::evaluate<Dim>(params_, state[i], F, dt);
      HenckyJ2::commit(state[i], u);
      Mat3 tau = u.dev_kirchhoff;
      tau.diagonal().array() += volumetric_.kirchhoff_pressure(J);
      p.stress[i] = SymTensor<Dim>::from(tau / J);
      for (Real s : p.stress[i].c) sum += s;
      max_speed = max_speed.cwiseMax((p.v[i].cwiseAbs().array() + wave_speed(J)).matrix());
    }
    WaveSpeedBound<Dim> bound;
    bound.max_speed = max_speed;
    bound.finite = std::isfinite(sum);
    return bound;
  }

  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const override {
    const Real* hoop = axisym::hoop_stretch_of(p);
    WaveSpeedBound<Dim> bound;
    for (Index i = 0; i < p.size(); ++i) {
      const Real c = wave_speed(axisym::volume_ratio(p, i, hoop));
      bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
    }
    return bound;
  }

  /// sum V_0 (W~ + U(J)), with G ||dev eps^e||^2 = ||dev tau||^2 / (4 G) and dev tau = J dev sigma, J; with the
  /// mixed volume Theta of the implicit scheme (field mixed_volume) U(Theta) instead of U(J) (eq. 99).
  void add_strain_energy(const ParticleSet<Dim>& p, ExactSum& e) const override {
    const auto& state = p.field(state_field);
    const Real* theta = p.has_field(keys::mixed_volume) ? p.field(keys::mixed_volume).data() : nullptr;
    const Real G = params_.shear_modulus, H = params_.hardening_modulus;
    const Real* hoop = axisym::hoop_stretch_of(p);
    for (Index i = 0; i < p.size(); ++i) {
      const Real J = axisym::volume_ratio(p, i, hoop);
      const Mat3 s = p.stress[i].full();
      const Mat3 dev_tau = J * (s - s.trace() / 3 * Mat3::Identity());
      const Real w = dev_tau.squaredNorm() / (4 * G) + 0.5 * H * state[i].xi * state[i].xi +
                     volumetric_.energy(theta ? theta[i] : J);
      e += p.volume0[i] * w;
    }
  }

  void add_dissipated_energy(const ParticleSet<Dim>& p, ExactSum& e) const override {
    const auto& state = p.field(state_field);
    for (Index i = 0; i < p.size(); ++i) e += p.volume0[i] * state[i].plastic_work;
  }

  bool append_output(std::string_view field, const ParticleSet<Dim>& p, std::vector<double>& out) const override {
    if (field != "plastic_strain") return false;
    for (const State& s : p.field(state_field)) out.push_back(s.xi);
    return true;
  }

  /// Dilatational wave speed about det F = J, m/s. In uniaxial strain the Cauchy stress is
  /// M ln(lambda)/lambda (M = K + 4G/3, lambda = J), whose Lagrangian modulus dP/dlambda = M (1 - ln J)/J^2
  /// gives the spatial speed c^2 = M (1 - ln J)/rho_0; never below the undeformed sqrt(M/rho_0). Plastic
  /// flow only softens the response, so the elastic speed bounds it.
  Real wave_speed(Real J) const {
    const Real M = params_.bulk_modulus + 4 * params_.shear_modulus / 3;
    return std::sqrt(M * std::max(Real(1), 1 - std::log(J)) / params_.density);
  }

 private:
  HenckyJ2Params params_;
  LogVolumetricEnergy volumetric_;
};

}  // namespace mpm::plasticity
