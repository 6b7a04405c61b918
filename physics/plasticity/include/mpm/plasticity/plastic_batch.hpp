#pragma once
/// \file plastic_batch.hpp
/// The batched Material interface for a law with history (elastoplastic.hpp): one virtual call per block
/// of particles, the inlined point law inside the loop. The history of every particle is one on-demand
/// field "plasticity" (PlasticState, read and written together), and the temperature the shared field
/// "temperature" (K), added only when the model tracks it. Both are resolved once per block, never per
/// particle. Outputs: plastic_strain, plastic_strain_rate, damage; energy audit: plastic_work.

#include <cmath>
#include <string>
#include <utility>

#include "mpm/material.hpp"
#include "mpm/plasticity/elastoplastic.hpp"

namespace mpm::plasticity {

template <int Dim, class Model>
class PlasticBatch final : public Material<Dim> {
 public:
  using Params = typename Model::Params;
  using State = PlasticState<Dim>;
  static constexpr const char* state_field = "plasticity";

  PlasticBatch(std::string key, const Params& params) : key_(std::move(key)), params_(params) {}
  std::string_view model() const override { return key_; }
  Real density() const override { return params_.density; }
  const Params& params() const { return params_; }

  void prepare_particles(ParticleSet<Dim>& p) const override {
    p.template add_field<State>(state_field, State{});
    if (params_.thermal) p.template add_field<Real>("temperature", params_.room_temperature);  // kept if present
  }

  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt) override {
    State* state = p.template field<State>(state_field).data();
    Real* temperature = params_.thermal ? p.template field<Real>("temperature").data() : nullptr;
    Real sum = 0;  // finite stresses have a finite sum
    Vec<Dim> max_v = Vec<Dim>::Zero();
    Real max_c2 = 0;
    for (Index i = begin; i != end; ++i) {
      const Mat<Dim> F = p.F[i];
      const Real J = F.determinant();
      Model::template update_point<Dim>(params_, F, Mat<Dim>(L[i - begin]), J, dt, p.volume0[i] * J, state[i],
                                        temperature ? temperature + i : nullptr, p.stress[i]);
      for (Real c : p.stress[i].c) sum += c;
      max_c2 = std::max(max_c2, Model::wave_speed_squared(params_, J));
      max_v = max_v.cwiseMax(VecU<Dim>(p.v[i].cwiseAbs()));
    }
    // max_a (|v_a| + c) <= max |v_a| + max c: one square root per block (slightly conservative)
    WaveSpeedBound<Dim> bound;
    bound.max_speed = (max_v.array() + std::sqrt(max_c2)).matrix();
    bound.finite = std::isfinite(sum);
    return bound;
  }

  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const override {
    WaveSpeedBound<Dim> bound;
    for (Index i = 0; i < p.size(); ++i) {
      const Real c = Model::wave_speed(params_, p.F[i].determinant());
      bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
    }
    return bound;
  }

  Real strain_energy(const ParticleSet<Dim>& p) const override {
    Real e = 0;  // serial: fixed summation order
    for (Index i = 0; i < p.size(); ++i)
      e += p.volume0[i] * Model::energy_density(params_, p.F[i].determinant(), p.stress[i].full());
    return e;
  }

  Real dissipated_energy(const ParticleSet<Dim>& p) const override {
    const auto& state = p.template field<State>(state_field);
    Real e = 0;
    for (Index i = 0; i < p.size(); ++i) e += p.volume0[i] * state[i].plastic_work;
    return e;
  }

  bool append_output(std::string_view field, const ParticleSet<Dim>& p, std::vector<double>& out) const override {
    Real State::*member = nullptr;
    if (field == "plastic_strain")
      member = &State::plastic_strain;
    else if (field == "plastic_strain_rate")
      member = &State::plastic_strain_rate;
    else if (field == "damage")
      member = &State::damage;
    else
      return false;
    for (const State& s : p.template field<State>(state_field)) out.push_back(s.*member);
    return true;
  }

 private:
  std::string key_;
  Params params_;
};

}  // namespace mpm::plasticity
