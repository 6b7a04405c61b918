#pragma once
/// \file soil_batch.hpp
/// A frictional soil as a material of the explicit schemes: a hypoelastic trial stress with the Hughes-Winget
/// rotation of the previous stress (objective for large rotations, theory eq. 18.12), then the model's return
/// mapping (`Return`: DruckerPrager, MohrCoulomb, or the rate law MuI, whose return takes the time step), one virtual
/// call per block and the point law inlined. The
/// plastic strain increment is recovered from the return, d eps_p = C^-1 : (sigma_trial - sigma) (eq. 18.13), so
/// that one bookkeeping serves every return (cone, apex, edges, cut-off).

#include <cmath>
#include <string_view>
#include <vector>

#include "mpm/materials/material.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/soils/soil_params.hpp"
#include "mpm/soils/soil_state.hpp"

namespace mpm::soils {

template <int Dim, class Return>
class SoilBatch final : public Material<Dim> {
 public:
  explicit SoilBatch(const SoilParams& params) : params_(params), return_(params) {}
  std::string_view model() const override { return Return::key; }
  Real density() const override { return params_.density; }
  const SoilParams& params() const { return params_; }
  const Return& return_mapping() const { return return_; }

  void prepare_particles(ParticleSet<Dim>& p) const override { p.add_field(keys::soil_state, SoilState{}); }

  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt) override {
    SoilState* state = p.field(keys::soil_state).data();
    const axisym::HoopFields hoop = axisym::hoop_fields(p);
    const Real c = params_.wave_speed();
    Real sum = 0;  // finite stresses have a finite sum
    Vec<Dim> max_speed = Vec<Dim>::Zero();
    for (Index i = begin; i != end; ++i) {
      const Mat3 l = embed<Dim>(Mat<Dim>(L[i - begin]), hoop ? hoop.rate[i] : 0);
      const Real J = axisym::volume_ratio(p, i, hoop.stretch);
      const Mat3 sigma = update_point(l, dt, J, p.stress[i].full(), state[i]);
      p.stress[i] = SymTensor<Dim>::from(sigma);
      for (Real s : p.stress[i].c) sum += s;
      max_speed = max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
    }
    WaveSpeedBound<Dim> bound;
    bound.max_speed = max_speed;
    bound.finite = std::isfinite(sum);
    return bound;
  }

  /// One point: the new Cauchy stress from the old one and the velocity gradient `l` over `dt`; `J` = det F at the
  /// end of the step (the plastic work is per reference volume). Updates `state`.
  Mat3 update_point(const Mat3& l, Real dt, Real J, const Mat3& sigma_old, SoilState& state) const {
    const Mat3 d = 0.5 * (l + l.transpose()) * dt;  // strain increment
    const Mat3 w = 0.5 * (l - l.transpose()) * dt;  // spin increment
    // Hughes-Winget: R = (I - w/2)^-1 (I + w/2), an exact rotation for any w (eq. 18.12).
    const Mat3 rotation = (Mat3::Identity() - 0.5 * w).inverse() * (Mat3::Identity() + 0.5 * w);
    const Real G = params_.shear_modulus, K = params_.bulk_modulus;
    const Real tr = d.trace();
    const Mat3 trial =
        rotation * sigma_old * rotation.transpose() + 2 * G * d + (K - 2 * G / 3) * tr * Mat3::Identity();
    // With softening the strength is that of the plastic strain at the start of the step (explicit, as the
    // plasticity module's hardening): the return is built for it.
    Mat3 sigma;
    if constexpr (requires(const Return& r) { r.return_map(trial, dt, state.plastic_volumetric_strain); })
      // a rate law (mu_i): the return needs the step, and the opening of the grains (the plastic volume strain)
      sigma = return_.return_map(trial, dt, state.plastic_volumetric_strain);
    else
      sigma = params_.softening.enabled ? Return(params_.softened(state.plastic_strain)).return_map(trial)
                                        : return_.return_map(trial);
    // d eps_p = C^-1 : (sigma_trial - sigma) = dev / (2G) + tr / (9K) 1 (eq. 18.13)
    const Mat3 relaxed = trial - sigma;
    const Real dp = relaxed.trace() / 3;
    const Mat3 de_dev = (relaxed - dp * Mat3::Identity()) / (2 * G);
    const Real dv = dp / K;
    if (dv != 0 || de_dev.squaredNorm() != 0) {
      state.plastic_strain += std::sqrt(2.0 / 3.0 * de_dev.squaredNorm());
      state.plastic_volumetric_strain += dv;
      state.plastic_work += J * ((sigma.array() * de_dev.array()).sum() + sigma.trace() / 3 * dv);
    }
    return sigma;
  }

  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const override {
    WaveSpeedBound<Dim> bound;
    const Real c = params_.wave_speed();
    for (Index i = 0; i < p.size(); ++i)
      bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
    return bound;
  }

  bool particle_wave_speeds(const ParticleSet<Dim>& p, std::vector<Real>& c) const override {
    c.assign(static_cast<std::size_t>(p.size()), params_.wave_speed());
    return true;
  }

  /// The elastic energy of the current stress, sigma : C^-1 : sigma / 2 = s:s/(4G) + p^2/(2K), per current volume,
  /// times J V_0.
  void add_strain_energy(const ParticleSet<Dim>& p, ExactSum& e) const override {
    const Real* hoop = axisym::hoop_stretch_of(p);
    for (Index i = 0; i < p.size(); ++i) {
      const Mat3 s = p.stress[i].full();
      const Real mean = s.trace() / 3;
      const Real w = (s - mean * Mat3::Identity()).squaredNorm() / (4 * params_.shear_modulus) +
                     mean * mean / (2 * params_.bulk_modulus);
      e += p.volume0[i] * axisym::volume_ratio(p, i, hoop) * w;
    }
  }

  void add_dissipated_energy(const ParticleSet<Dim>& p, ExactSum& e) const override {
    const auto& state = p.field(keys::soil_state);
    for (Index i = 0; i < p.size(); ++i) e += p.volume0[i] * state[static_cast<std::size_t>(i)].plastic_work;
  }

  bool append_output(std::string_view field, const ParticleSet<Dim>& p, std::vector<double>& out) const override {
    const auto& state = p.field(keys::soil_state);
    if (field == "plastic_strain" || field == "plastic_volumetric_strain") out.reserve(out.size() + state.size());
    if (field == "plastic_strain") {
      for (const SoilState& s : state) out.push_back(s.plastic_strain);
      return true;
    }
    if (field == "plastic_volumetric_strain") {
      for (const SoilState& s : state) out.push_back(s.plastic_volumetric_strain);
      return true;
    }
    return false;
  }

 private:
  SoilParams params_;
  Return return_;
};

}  // namespace mpm::soils
