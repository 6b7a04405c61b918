#pragma once
/// \file material_batch.hpp
/// CRTP base that turns a per-point law into the batched Material interface. A model `M` provides
///   static constexpr const char* key;
///   struct Params { ... };                       (constants, built once from the scene)
///   static SymTensor<Dim>-free Mat3 update_point(const Params&, const PointKinematics&, const Mat3& stress_old);
///   static Real wave_speed(const Params&, Real J);     dilatational wave speed at det F = J (m/s)
///   static Real energy_density(const Params&, const Mat3& F, const Mat3& stress);  per reference volume (J/m^3)
/// The update is pure (old state in, new state out) so that an implicit scheme can call it for trial
/// deformations without committing anything.

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>

#include "mpm/material.hpp"

namespace mpm {

template <int Dim, class Model>
class MaterialBatch final : public Material<Dim> {
 public:
  using Params = typename Model::Params;
  explicit MaterialBatch(const Params& params) : params_(params) {}
  std::string_view model() const override { return Model::key; }
  Real density() const override { return params_.density; }
  const Params& params() const { return params_; }

  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, Real dt) override {
    return tbb::parallel_reduce(
        tbb::blocked_range<Index>(begin, end, 1024), WaveSpeedBound<Dim>{},
        [&](const tbb::blocked_range<Index>& r, WaveSpeedBound<Dim> bound) {
          for (Index i = r.begin(); i != r.end(); ++i) {
            PointKinematics k;
            k.F = embed<Dim>(p.F[i], 1);
            k.L = embed<Dim>(p.L[i], 0);
            k.J = p.F[i].determinant();
            k.dt = dt;
            const Mat3 s = Model::update_point(params_, k, p.stress[i].full());
            p.stress[i] = SymTensor<Dim>::from(s);
            bound.finite = bound.finite && s.allFinite();
            const Real c = Model::wave_speed(params_, k.J);
            bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
          }
          return bound;
        },
        [](WaveSpeedBound<Dim> a, const WaveSpeedBound<Dim>& b) {
          a.merge(b);
          return a;
        });
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
    Real e = 0;  // serial: a fixed summation order keeps the energy log bit-reproducible
    for (Index i = 0; i < p.size(); ++i)
      e += p.volume0[i] * Model::energy_density(params_, embed<Dim>(p.F[i], 1), p.stress[i].full());
    return e;
  }

 private:
  Params params_;
};

}  // namespace mpm
