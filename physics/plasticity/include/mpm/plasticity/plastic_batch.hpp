#pragma once
/// \file plastic_batch.hpp
/// The batched Material interface for a law with history (elastoplastic.hpp): one virtual call per block
/// of particles, the inlined point law inside the loop. The history of every particle is one on-demand
/// field (keys::plastic_state: PlasticState, read and written together), and the temperature the shared
/// field mpm::keys::temperature (K), added only when the model tracks it. Both are resolved once per block,
/// never per particle. Outputs: the list of output_fields.hpp; energy audit: plastic_work.

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "mpm/materials/material.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/plasticity/elastoplastic.hpp"
#include "mpm/plasticity/field_keys.hpp"
#include "mpm/plasticity/output_fields.hpp"
#include "mpm/schemes/axisymmetric.hpp"

namespace mpm::plasticity {

template <int Dim, class Model>
class PlasticBatch final : public Material<Dim> {
 public:
  using Params = typename Model::Params;
  using State = PlasticState<Dim>;
  static constexpr FieldKey<State> state_field = keys::plastic_state<Dim>;

  PlasticBatch(std::string key, const Params& params) : key_(std::move(key)), params_(params) {}
  std::string_view model() const override { return key_; }
  Real density() const override { return params_.density; }
  const Params& params() const { return params_; }

  void prepare_particles(ParticleSet<Dim>& p) const override {
    p.add_field(state_field, State{});
    if (params_.thermal) p.add_field(mpm::keys::temperature, params_.room_temperature);  // kept if present
  }

  /// Every particle runs the vector law, in packs aligned to the index (particles g .. g + lane_count - 1, g a
  /// multiple of lane_count); a pack that the block or the end of the set cuts is padded with copies of one of
  /// its particles, whose results are dropped. A lane's result depends on its own particle only (the lanes
  /// never mix: a branch taken for one lane is a select for the others), so a particle's update is the same
  /// bits whatever its index, its pack-mates and the blocks TBB cuts the set into, which depend on the thread
  /// count, on timing and (later) on the rank a particle lives on. The scalar law is not used here: it agrees
  /// with the vector law only to round-off (its log, exp and pow are the C library's).
  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt) override {
    if constexpr (Dim == 2)  // axisymmetric bodies: F_tt and L_tt join the law (one test per block)
      if (const axisym::HoopFields hoop = axisym::hoop_fields(p)) return update_block<true>(p, begin, end, L, dt, hoop);
    return update_block<false>(p, begin, end, L, dt, {});
  }

  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const override {
    const Real* hoop = axisym::hoop_stretch_of(p);
    const auto& state = p.field(state_field);
    WaveSpeedBound<Dim> bound;
    for (Index i = 0; i < p.size(); ++i) {
      const Real c = Model::wave_speed(params_, axisym::volume_ratio(p, i, hoop), state[i].damage);
      bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
    }
    return bound;
  }

  bool particle_wave_speeds(const ParticleSet<Dim>& p, std::vector<Real>& c) const override {
    const Real* hoop = axisym::hoop_stretch_of(p);
    const auto& state = p.field(state_field);
    c.resize(static_cast<std::size_t>(p.size()));
    for (Index i = 0; i < p.size(); ++i)
      c[static_cast<std::size_t>(i)] = Model::wave_speed(params_, axisym::volume_ratio(p, i, hoop), state[i].damage);
    return true;
  }

  /// A failed particle is fully damaged (D = 1): no deviatoric stress, no plastic flow, no tension (eq. B.16 and
  /// docs/errata.md #28), from now on.
  void mark_failed(ParticleSet<Dim>& p, std::span<const Index> which) const override {
    auto& state = p.field(state_field);
    for (const Index i : which) state[static_cast<std::size_t>(i)].damage = 1;
  }

  void add_strain_energy(const ParticleSet<Dim>& p, ExactSum& e) const override {
    const Real* hoop = axisym::hoop_stretch_of(p);
    for (Index i = 0; i < p.size(); ++i)
      e += p.volume0[i] * Model::energy_density(params_, axisym::volume_ratio(p, i, hoop), p.stress[i].full());
  }

  void add_dissipated_energy(const ParticleSet<Dim>& p, ExactSum& e) const override {
    const auto& state = p.field(state_field);
    for (Index i = 0; i < p.size(); ++i) e += p.volume0[i] * state[i].plastic_work;
  }

  bool append_output(std::string_view field, const ParticleSet<Dim>& p, std::vector<double>& out) const override {
    Real State::*member = nullptr;
    for (const auto& o : plastic_outputs<Dim>)
      if (field == o.name) member = o.member;
    if (!member) return false;
    for (const State& s : p.field(state_field)) out.push_back(s.*member);
    return true;
  }

 private:
  /// J (with F_tt when `Hoop`) and the particle size of the viscosity length: the current volume, or the
  /// meridian area of an axisymmetric particle.
  template <bool Hoop>
  static void size_of(const ParticleSet<Dim>& p, Index i, [[maybe_unused]] const axisym::HoopFields& hoop, Real& J,
                      Real& size) {
    J = p.F[i].determinant();
    if constexpr (Hoop) {
      J *= hoop.stretch[i];
      size = axisym::meridian_area(p.volume0[i] * J, p.x[i][0]);
    } else {
      size = p.volume0[i] * J;
    }
  }

  template <bool Hoop>
  WaveSpeedBound<Dim> update_block(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt,
                                   const axisym::HoopFields& hoop) {
    State* state = p.field(state_field).data();
    Real* temperature = params_.thermal ? p.field(mpm::keys::temperature).data() : nullptr;
    Vec<Dim> max_speed = Vec<Dim>::Zero();
    for (Index g = begin - begin % lane_count; g < end; g += lane_count) {
      const Index first = std::max(g, begin), last = std::min<Index>(g + lane_count, end);
      update_pack<Hoop>(p, g, first, last, L + (first - begin), dt, state, temperature, hoop, max_speed);
    }
    Real sum = 0;  // finite stresses have a finite sum
    for (Index k = begin; k != end; ++k)
      for (Real c : p.stress[k].c) sum += c;
    WaveSpeedBound<Dim> bound;
    bound.max_speed = max_speed;
    bound.finite = std::isfinite(sum);
    return bound;
  }

  /// Particles first .. last - 1 of the pack that starts at particle g (L: their velocity gradients) through
  /// the vector law; lanes outside [first, last) repeat particle `first` and are not stored. Raises
  /// max_speed to max (|v_a| + c) over the particles (eq. 2.72 per particle, so that the bound, and the time
  /// step, do not depend on how the particles are cut into blocks).
  template <bool Hoop>
  void update_pack(ParticleSet<Dim>& p, Index g, Index first, Index last, const MatU<Dim>* L, Real dt, State* state,
                   Real* temperature, [[maybe_unused]] const axisym::HoopFields& hoop, Vec<Dim>& max_speed) const {
    PointLanes<Dim, Pack> lanes;
    if constexpr (!Hoop) lanes.L_hoop = Pack::Zero();
    for (int l = 0; l < lane_count; ++l) {
      const Index k = g + l >= first && g + l < last ? g + l : first;
      const Mat<Dim> F = p.F[k];
      for (int r = 0; r < Dim; ++r)
        for (int c = 0; c < Dim; ++c) {
          lanes.F[r][c][l] = F(r, c);
          lanes.L[r][c][l] = L[k - first](r, c);
        }
      if constexpr (Hoop) lanes.L_hoop[l] = hoop.rate[k];
      size_of<Hoop>(p, k, hoop, lanes.J[l], lanes.volume[l]);
      lanes.load_state(state[k], l);
      lanes.temperature[l] = temperature ? temperature[k] : params_.room_temperature;
      for (int c = 0; c < SymTensor<Dim>::size; ++c) lanes.stress[c][l] = p.stress[k].c[c];
    }
    Model::template update<Dim, Pack>(params_, dt, temperature != nullptr, lanes);
    for (Index k = first; k < last; ++k) {
      const int l = static_cast<int>(k - g);
      lanes.store_state(state[k], l);
      if (temperature) temperature[k] = lanes.temperature[l];
      for (int c = 0; c < SymTensor<Dim>::size; ++c) p.stress[k].c[c] = lanes.stress[c][l];
    }
    const Pack c = Model::wave_speed_squared(params_, lanes.J, lanes.damage).sqrt();
    for (Index k = first; k < last; ++k)
      max_speed = max_speed.cwiseMax((p.v[k].cwiseAbs().array() + c[static_cast<int>(k - g)]).matrix());
  }

  std::string key_;
  Params params_;
};

}  // namespace mpm::plasticity
