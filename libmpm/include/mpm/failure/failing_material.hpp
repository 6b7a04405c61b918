#pragma once
/// \file failure/failing_material.hpp
/// The material of a body whose scene material has a `failure:` block: the model's own material, wrapped. After the
/// model's stress update of a block, a failed particle (action fail, field keys::failed) keeps only its compressive
/// pressure (eq. 16.2), and every particle integrates the work its stress does, w += J sigma_mid : D dt per reference
/// volume with sigma_mid the mean of the stresses before and after the step (eq. 16.4, field keys::stress_work).
/// Its strain energy is then booked as V0 (w - w_p), the work of the stress less the plastic work the model
/// dissipated: the stress a failed particle no longer carries is not counted as stored energy, whatever the
/// model's energy density would say of its deformation (an expanded failed particle, J >> 1, would otherwise book the
/// equation of state's energy of that expansion). Everything else is the model's.

#include <memory>
#include <string>
#include <vector>

#include "mpm/failure/failure_criteria.hpp"
#include "mpm/materials/material.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/schemes/axisymmetric.hpp"

namespace mpm {

template <int Dim>
class FailingMaterial final : public Material<Dim> {
 public:
  explicit FailingMaterial(std::unique_ptr<Material<Dim>> model) : model_(std::move(model)) {}
  std::string_view model() const override { return model_->model(); }
  Real density() const override { return model_->density(); }
  /// The wrapped model's material.
  const Material<Dim>& wrapped() const { return *model_; }

  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt) override {
    thread_local std::vector<SymTensor<Dim>> before;
    before.assign(p.stress.begin() + begin, p.stress.begin() + end);
    const WaveSpeedBound<Dim> bound = model_->update_stress(p, begin, end, L, dt);
    const Real* failed = p.field(keys::failed).data();
    Real* work = p.field(keys::stress_work).data();
    const Real* hoop_stretch = axisym::hoop_stretch_of(p);
    const Real* hoop_rate = hoop_stretch ? p.field(keys::hoop_velocity_gradient).data() : nullptr;
    for (Index i = begin; i < end; ++i) {
      if (failed[i] != 0) p.stress[i] = pressure_only(p.stress[i]);
      const SymTensor<Dim>& s0 = before[static_cast<std::size_t>(i - begin)];
      const SymTensor<Dim>& s1 = p.stress[i];
      const MatU<Dim>& l = L[i - begin];
      // sigma_mid : D, D = sym(L) (with the hoop rate L_tt on an axisymmetric body; 0 out of plane otherwise)
      Real power = 0.5 * (s0.c[0] + s1.c[0]) * l(0, 0);
      if constexpr (Dim >= 2)
        power += 0.5 * (s0.c[1] + s1.c[1]) * l(1, 1) + 0.5 * (s0.c[3] + s1.c[3]) * (l(0, 1) + l(1, 0));
      if constexpr (Dim == 2)
        if (hoop_rate) power += 0.5 * (s0.c[2] + s1.c[2]) * hoop_rate[i];
      if constexpr (Dim == 3)
        power += 0.5 * (s0.c[2] + s1.c[2]) * l(2, 2) + 0.5 * (s0.c[4] + s1.c[4]) * (l(1, 2) + l(2, 1)) +
                 0.5 * (s0.c[5] + s1.c[5]) * (l(0, 2) + l(2, 0));
      work[i] += axisym::volume_ratio(p, i, hoop_stretch) * power * dt;
    }
    return bound;
  }
  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const override { return model_->wave_speed_bound(p); }
  /// sum V0 (w - w_p) (eq. 16.4): the work of each particle's stress less the plastic work its model dissipated.
  void add_strain_energy(const ParticleSet<Dim>& p, ExactSum& sum) const override {
    const auto& work = p.field(keys::stress_work);
    thread_local std::vector<double> dissipated;
    dissipated.clear();
    const bool plastic = model_->append_output("plastic_work", p, dissipated);
    for (Index i = 0; i < p.size(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      sum += p.volume0[i] * (plastic ? work[k] - dissipated[k] : work[k]);
    }
  }
  void add_dissipated_energy(const ParticleSet<Dim>& p, ExactSum& sum) const override {
    model_->add_dissipated_energy(p, sum);
  }
  void prepare_particles(ParticleSet<Dim>& p) const override {
    model_->prepare_particles(p);
    p.add_field(keys::failed, Real(0));
    p.add_field(keys::stress_work, Real(0));
  }
  bool append_output(std::string_view field, const ParticleSet<Dim>& p, std::vector<double>& out) const override {
    if (field == "failed") {
      for (const Real f : p.field(keys::failed)) out.push_back(f);
      return true;
    }
    return model_->append_output(field, p, out);
  }
  Real kinematic_viscosity() const override { return model_->kinematic_viscosity(); }
  std::string state_warning(const ParticleSet<Dim>& p) const override { return model_->state_warning(p); }
  bool particle_wave_speeds(const ParticleSet<Dim>& p, std::vector<Real>& c) const override {
    return model_->particle_wave_speeds(p, c);
  }
  void mark_failed(ParticleSet<Dim>& p, std::span<const Index> which) const override {
    model_->mark_failed(p, which);
    auto& failed = p.field(keys::failed);
    for (const Index i : which) {
      failed[static_cast<std::size_t>(i)] = 1;
      p.stress[i] = pressure_only(p.stress[i]);
    }
  }

 private:
  std::unique_ptr<Material<Dim>> model_;
};

}  // namespace mpm
