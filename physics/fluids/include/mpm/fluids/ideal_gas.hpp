#pragma once
/// \file ideal_gas.hpp
/// Ideal gas for shock tubes (review §5.4, eqs 5.32-5.35): sigma = -(p + q) I with p = (gamma - 1) rho e,
/// rho = rho0 / J, the specific internal energy e per particle (field "internal_energy", J/kg) and the
/// artificial viscosity q = rho L_e (c_2 L_e tr(D)^2 - c_1 a tr(D)) when tr(D) < 0 (eq. 5.35; a = sqrt(gamma p
/// / rho), coefficients c_1 linear and c_2 quadratic). L_e is the particle's current length V^(1/d).
/// Energy (eq. 5.33 with D, digest erratum): de/dt = -(p + q) tr(D) / rho, taken implicitly in p so that the
/// update is exact for the pressure work: e' = (e - dt q tr D / rho) / (1 + dt (gamma - 1) tr D).
/// The stored energy of the audit is the internal energy sum m e: kinetic + internal is conserved.

#include <cmath>
#include <string_view>
#include <vector>

#include "mpm/material.hpp"

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
  explicit IdealGas(const IdealGasParams& c) : c_(c) {}
  std::string_view model() const override { return "ideal_gas"; }
  Real density() const override { return c_.density; }
  const IdealGasParams& params() const { return c_; }

  void prepare_particles(ParticleSet<Dim>& p) const override {
    p.template add_field<Real>("internal_energy", c_.initial_energy());
    for (Index i = 0; i < p.size(); ++i) p.stress[i] = SymTensor<Dim>::from(-c_.initial_pressure * Mat3::Identity());
  }

  WaveSpeedBound<Dim> update_stress(ParticleSet<Dim>& p, Index begin, Index end, const MatU<Dim>* L, Real dt) override {
    auto& energy = p.template field<Real>("internal_energy");
    WaveSpeedBound<Dim> bound;
    for (Index i = begin; i != end; ++i) {
      const Real J = p.F[i].determinant();
      const Real rho = c_.density / J;
      const Real trD = Mat<Dim>(L[i - begin]).trace();
      const Real e = energy[i];
      const Real a = std::sqrt(std::max<Real>(0, c_.gamma * (c_.gamma - 1) * e));
      Real q = 0;
      if (trD < 0) {
        const Real length = std::pow(p.volume0[i] * J, Real(1) / Dim);
        q = rho * length * (c_.viscosity_quadratic * length * trD * trD - c_.viscosity_linear * a * trD);
      }
      const Real e_new = (e - dt * q * trD / rho) / (1 + dt * (c_.gamma - 1) * trD);
      energy[i] = e_new;
      const Real pressure = (c_.gamma - 1) * rho * e_new;
      p.stress[i] = SymTensor<Dim>::from(-(pressure + q) * Mat3::Identity());
      bound.finite = bound.finite && std::isfinite(pressure + q) && e_new >= 0;
      const Real speed = std::sqrt(std::max<Real>(0, c_.gamma * (c_.gamma - 1) * e_new));
      bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + speed).matrix());
    }
    return bound;
  }

  WaveSpeedBound<Dim> wave_speed_bound(const ParticleSet<Dim>& p) const override {
    const auto& energy = p.template field<Real>("internal_energy");
    WaveSpeedBound<Dim> bound;
    for (Index i = 0; i < p.size(); ++i) {
      const Real speed = std::sqrt(std::max<Real>(0, c_.gamma * (c_.gamma - 1) * energy[i]));
      bound.max_speed = bound.max_speed.cwiseMax((p.v[i].cwiseAbs().array() + speed).matrix());
    }
    return bound;
  }

  Real strain_energy(const ParticleSet<Dim>& p) const override {
    const auto& energy = p.template field<Real>("internal_energy");
    Real sum = 0;
    for (Index i = 0; i < p.size(); ++i) sum += p.mass[i] * energy[i];
    return sum;
  }

  bool append_output(std::string_view field, const ParticleSet<Dim>& p, std::vector<double>& out) const override {
    if (field != "internal_energy") return false;
    const auto& energy = p.template field<Real>("internal_energy");
    out.insert(out.end(), energy.begin(), energy.end());
    return true;
  }

 private:
  IdealGasParams c_;
};

}  // namespace mpm::fluids
