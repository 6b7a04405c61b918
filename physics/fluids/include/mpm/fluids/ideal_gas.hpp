#pragma once
/// \file ideal_gas.hpp
/// Ideal gas for shock tubes (review §5.4, eqs 5.32-5.35): sigma = -(p + q) I with p = (gamma - 1) rho e,
/// rho = rho0 / J, the specific internal energy e per particle (field keys::internal_energy, J/kg; written by
/// the output field `internal_energy`) and the
/// artificial viscosity q = rho L_e (c_2 L_e tr(D)^2 - c_1 a tr(D)) when tr(D) < 0 (eq. 5.35; a = sqrt(gamma p
/// / rho), coefficients c_1 linear and c_2 quadratic). L_e is the particle's current length V^(1/d).
/// Energy (eq. 5.33 with D, docs/errata.md #11): de/dt = -(p + q) tr(D) / rho, taken implicitly in p so that the
/// update is exact for the pressure work: e' = (e - dt q tr D / rho) / (1 + dt (gamma - 1) tr D).
/// The stored energy of the audit is the internal energy sum m e: kinetic + internal is conserved.

#include <cmath>
#include <string_view>
#include <vector>

#include "mpm/fluids/field_keys.hpp"
#include "mpm/materials/material.hpp"
#include "mpm/schemes/axisymmetric.hpp"

namespace mpm::fluids {

struct IdealGasParams {
  Real density;                  ///< rho0 at F = I, kg/m^3
  Real gamma;                    ///< ratio of specific heats
  Real initial_pressure;         ///< p0 at F = I, Pa: e0 = p0 / ((gamma - 1) rho0)
  Real viscosity_linear = 0;     ///< c_1
  Real viscosity_quadratic = 0;  ///< c_2
  Real initial_energy() const { return initial_pressure / ((gamma - 1) * density); }
};

template <int Dim>
class IdealGas final : public Material<Dim> {
 public:
  explicit IdealGas(const IdealGasParams& c) : params_(c) {}
  std::string_view model() const override { return "ideal_gas"; }
  Real density() const override { return params_.density; }
  const IdealGasParams& params() const { return params_; }

  void prepare_particles(ParticleSet<Dim>& p) const override {
    p.add_field(keys::internal_energy, params_.initial_energy());
    for (Index i = 0; i < p.size(); ++i)
      p.stress[i] = SymTensor<Dim>::from(-params_.initial_pressure * Mat3::Identity());
  }

  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt) override {
    auto& energy = p.field(keys::internal_energy);
    const axisym::HoopFields hoop = axisym::hoop_fields(p);  // axisymmetric: F_tt in J, L_tt in tr D
    WaveSpeedBound<Dim> bound;
    for (Index i = begin; i != end; ++i) {
      const Real J = axisym::volume_ratio(p, i, hoop.stretch);
      const Real rho = params_.density / J;
      const Real trD = Mat<Dim>(L[i - begin]).trace() + (hoop ? hoop.rate[i] : 0);
      const Real e = energy[i];
      const Real a = std::sqrt(std::max<Real>(0, params_.gamma * (params_.gamma - 1) * e));
      Real q = 0;
      if (trD < 0) {  // L_e: the particle's length, from its meridian area when axisymmetric
        const Real size = hoop ? axisym::meridian_area(p.volume0[i] * J, p.x[i][0]) : p.volume0[i] * J;
        const Real length = std::pow(size, Real(1) / Dim);
        q = rho * length * (params_.viscosity_quadratic * length * trD * trD - params_.viscosity_linear * a * trD);
      }
      const Real e_new = (e - dt * q * trD / rho) / (1 + dt * (params_.gamma - 1) * trD);
      energy[i] = e_new;
      const Real pressure = (params_.gamma - 1) * rho * e_new;
      p.stress[i] = SymTensor<Dim>::from(-(pressure + q) * Mat3::Identity());
      bound.finite = bound.finite && std::isfinite(pressure + q) && e_new >= 0;
      const Real speed = std::sqrt(std::max<Real>(0, params_.gamma * (params_.gamma - 1) * e_new));
      bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + speed).matrix());
    }
    return bound;
  }

  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const override {
    const auto& energy = p.field(keys::internal_energy);
    WaveSpeedBound<Dim> bound;
    for (Index i = 0; i < p.size(); ++i) {
      const Real speed = std::sqrt(std::max<Real>(0, params_.gamma * (params_.gamma - 1) * energy[i]));
      bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + speed).matrix());
    }
    return bound;
  }

  void add_strain_energy(const ParticleSet<Dim>& p, ExactSum& sum) const override {
    const auto& energy = p.field(keys::internal_energy);
    for (Index i = 0; i < p.size(); ++i) sum += p.mass[i] * energy[i];
  }

 private:
  IdealGasParams params_;
};

}  // namespace mpm::fluids
