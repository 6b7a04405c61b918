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
/// Optional: `static Real kinematic_viscosity(const Params&)` (m^2/s, for the viscous time-step bound) and
/// `static std::string state_warning(const Params&, Real J_min, Real J_max)` (see Material::state_warning).
/// A model may also provide `template <int Dim> static void update_packed(const Params&, const Mat<Dim>& F,
/// const Mat<Dim>& L, Real J, Real dt, SymTensor<Dim>& stress)`, the same law written on the packed
/// in-plane storage; the batch loop then uses it (the elastic laws do: it avoids 3x3 round trips), and
/// `update_packed_axisymmetric(params, F, L, F_tt, L_tt, J, dt, stress)` for axisymmetric bodies (else those
/// take the 3x3 law with F_tt and L_tt on the diagonal, axisymmetric.hpp).
/// Optional: `static constexpr bool tracks_deformation = false` for a law that reads no F
/// (Material::tracks_deformation). Optional: `static bool volumetric_only(const Params&)`, for a law that reads F
/// through J = det F alone (a fluid); true when F is to keep its volume only: the batch then replaces the in-plane F by
/// J_p^(1/Dim) I before the update (J_p its determinant; the hoop stretch and so J unchanged), so that no isochoric
/// distortion accumulates. When it is false the batch still does so for a particle whose F is distorted beyond the
/// precision of its determinant (eps ||F||_F^Dim > 1e-8 J_p, the round-off of det F above 1e-8 of its value): a fluid
/// sheared for long has F entries of 1e8 whose determinant is round-off, and a particle "inverts" that was never
/// compressed. Below that distortion F is kept whole (the cpGIMP domains follow it).

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "mpm/materials/material.hpp"
#include "mpm/schemes/axisymmetric.hpp"

namespace mpm {

template <int Dim, class Model>
class MaterialBatch final : public Material<Dim> {
 public:
  using Params = typename Model::Params;
  static constexpr bool has_packed_update = requires(const Params& c, const Mat<Dim>& m, SymTensor<Dim>& s) {
    Model::template update_packed<Dim>(c, m, m, Real(1), Real(1), s);
  };
  static constexpr bool has_packed_axisymmetric_update = requires(const Params& c, const Mat<2>& m, SymTensor<2>& s) {
    Model::update_packed_axisymmetric(c, m, m, Real(1), Real(0), Real(1), Real(1), s);
  };
  explicit MaterialBatch(const Params& params) : params_(params) {}
  std::string_view model() const override { return Model::key; }
  Real density() const override { return params_.density; }
  const Params& params() const { return params_; }

  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt) override {
    if constexpr (Dim == 2)  // one test per block: the loop itself is compiled for either kind of body
      if (const axisym::HoopFields hoop = axisym::hoop_fields(p)) return update_block<true>(p, begin, end, L, dt, hoop);
    return update_block<false>(p, begin, end, L, dt, {});
  }

  Real kinematic_viscosity() const override {
    if constexpr (requires(const Params& c) { Model::kinematic_viscosity(c); })
      return Model::kinematic_viscosity(params_);
    else
      return 0;
  }
  bool tracks_deformation() const override {
    if constexpr (requires { Model::tracks_deformation; })
      return Model::tracks_deformation;
    else
      return true;
  }
  std::string state_warning(const ParticleSet<Dim>& p) const override {
    if constexpr (requires(const Params& c, Real J) { Model::state_warning(c, J, J); }) {
      const Real* hoop = axisym::hoop_stretch_of(p);
      Real lo = 1, hi = 1;  // extreme det F of the body
      for (Index i = 0; i < p.size(); ++i) {
        const Real J = axisym::volume_ratio(p, i, hoop);
        lo = std::min(lo, J);
        hi = std::max(hi, J);
      }
      return Model::state_warning(params_, lo, hi);
    } else {
      return {};
    }
  }

  bool particle_wave_speeds(const ParticleSet<Dim>& p, std::vector<Real>& c) const override {
    const Real* hoop = axisym::hoop_stretch_of(p);
    c.resize(static_cast<std::size_t>(p.size()));
    for (Index i = 0; i < p.size(); ++i)
      c[static_cast<std::size_t>(i)] = Model::wave_speed(params_, axisym::volume_ratio(p, i, hoop));
    return true;
  }

  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const override {
    const Real* hoop = axisym::hoop_stretch_of(p);
    WaveSpeedBound<Dim> bound;
    for (Index i = 0; i < p.size(); ++i) {
      const Real c = Model::wave_speed(params_, axisym::volume_ratio(p, i, hoop));
      bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
    }
    return bound;
  }

  void add_strain_energy(const ParticleSet<Dim>& p, ExactSum& e) const override {
    const Real* hoop = axisym::hoop_stretch_of(p);
    for (Index i = 0; i < p.size(); ++i)
      e += p.volume0[i] *
           Model::energy_density(params_, axisym::deformation_gradient_3x3(p, i, hoop), p.stress[i].full());
  }

 private:
  /// The batch loop; `Hoop`: an axisymmetric body, whose F_tt and L_tt (`hoop`) join the law.
  template <bool Hoop>
  WaveSpeedBound<Dim> update_block(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt,
                                   [[maybe_unused]] const axisym::HoopFields& hoop) {
    bool finite = true;
    Vec<Dim> max_speed = Vec<Dim>::Zero();
    for (Index i = begin; i != end; ++i) {
      if constexpr (requires(const Params& c) { Model::volumetric_only(c); })
        if (const Real J_p = p.F[i].determinant(); J_p > 0)  // else the stability guard reports it
          if (Model::volumetric_only(params_) || determinant_is_round_off(p.F[i], J_p))
            p.F[i] = MatU<Dim>(std::pow(J_p, Real(1) / Dim) * Mat<Dim>::Identity());
      Real J = p.F[i].determinant();
      if constexpr (Hoop) J *= hoop.stretch[i];
      if constexpr (Hoop && has_packed_axisymmetric_update) {
        Model::update_packed_axisymmetric(params_, p.F[i], L[i - begin], hoop.stretch[i], hoop.rate[i], J, dt,
                                          p.stress[i]);
      } else if constexpr (!Hoop && has_packed_update) {
        Model::template update_packed<Dim>(params_, p.F[i], L[i - begin], J, dt, p.stress[i]);
      } else {
        PointKinematics k;
        k.F = embed<Dim>(p.F[i], Hoop ? hoop.stretch[i] : 1);
        k.L = embed<Dim>(Mat<Dim>(L[i - begin]), Hoop ? hoop.rate[i] : 0);
        k.J = J;
        k.dt = dt;
        p.stress[i] = SymTensor<Dim>::from(Model::update_point(params_, k, p.stress[i].full()));
      }
      Real sum = 0;
      for (Real c : p.stress[i].c) sum += c;
      finite = finite && std::isfinite(sum);
      const Real c = Model::wave_speed(params_, J);
      max_speed = max_speed.cwiseMax((p.v[i].cwiseAbs().array() + c).matrix());
    }
    WaveSpeedBound<Dim> bound;
    bound.max_speed = max_speed;
    bound.finite = finite;
    return bound;
  }

  /// Whether det F = J_p of an F with entries of size ||F||_F has lost its precision: its round-off,
  /// eps ||F||_F^Dim, exceeds 1e-8 J_p (in 2D at ||F|| ~ 7e3 J^(1/2), in 3D at ~ 360 J^(1/3)).
  static bool determinant_is_round_off(const MatU<Dim>& F, Real J_p) {
    const Real squared = F.squaredNorm();
    Real size = squared;  // ||F||^Dim without pow: this runs for every fluid particle every step
    if constexpr (Dim == 1) size = std::sqrt(squared);
    if constexpr (Dim == 3) size = squared * std::sqrt(squared);
    return std::numeric_limits<Real>::epsilon() * size > 1e-8 * J_p;
  }

  Params params_;
};

}  // namespace mpm
