#pragma once
// Builders of the plastic materials from validated scene parameters, instantiated once per dimension
// (make_plastic_material_{1,2,3}d.cpp, compiled in parallel).
#include <memory>

#include "mpm/materials/elastic_constants.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/plasticity/plastic_batch.hpp"
#include "mpm/plasticity/register.hpp"

namespace mpm::plasticity::detail {

/// The constants every plastic model shares (parameter names and defaults: register.cpp, filled in by the
/// scene loader). Optional parameters switch a feature on; the parameters of a feature are read only when it is
/// on, with material_parameter() (the given value or the spec's default).
inline PlasticityConstants constants(const MaterialDescription& d) {
  const auto& p = d.parameters;
  const ElasticConstants e = ElasticConstants::from_parameters(p);
  PlasticityConstants c;
  c.density = e.density;
  c.shear_modulus = e.mu;
  c.bulk_modulus = e.bulk;
  c.reference_strain_rate = p.at("reference_strain_rate");
  c.damage_enabled = p.count("damage_d1") != 0;
  if (c.damage_enabled) {
    c.damage.d1 = p.at("damage_d1");
    c.damage.d2 = material_parameter(d, "damage_d2");
    c.damage.d3 = material_parameter(d, "damage_d3");
    c.damage.d4 = material_parameter(d, "damage_d4");
  }
  c.damage.evolution_factor = p.at("damage_evolution_factor");
  c.thermal = p.count("specific_heat") != 0;
  if (c.thermal) {
    c.specific_heat = p.at("specific_heat");
    c.thermal_expansion = material_parameter(d, "thermal_expansion");
  }
  c.taylor_quinney = p.at("taylor_quinney_coefficient");
  c.room_temperature = p.at("room_temperature");
  c.viscosity_linear = p.at("artificial_viscosity_linear");
  c.viscosity_quadratic = p.at("artificial_viscosity_quadratic");
  return c;
}

template <int Dim, class Flow>
std::unique_ptr<Material<Dim>> make_with_eos(const char* key, const PlasticityConstants& c, const Flow& flow,
                                             const MaterialDescription& d) {
  const auto& p = d.parameters;
  if (p.count("bulk_sound_speed")) {
    ElastoplasticParams<Flow, MieGruneisenEos> params;
    static_cast<PlasticityConstants&>(params) = c;
    params.flow = flow;
    params.eos = {c.density, p.at("bulk_sound_speed"), material_parameter(d, "hugoniot_slope"),
                  material_parameter(d, "gruneisen_gamma")};
    return std::make_unique<PlasticBatch<Dim, Elastoplastic<Flow, MieGruneisenEos>>>(key, params);
  }
  ElastoplasticParams<Flow, LinearEos> params;
  static_cast<PlasticityConstants&>(params) = c;
  params.flow = flow;
  params.eos = {c.bulk_modulus};
  return std::make_unique<PlasticBatch<Dim, Elastoplastic<Flow, LinearEos>>>(key, params);
}

}  // namespace mpm::plasticity::detail

namespace mpm::plasticity {

template <int Dim>
std::unique_ptr<Material<Dim>> make_johnson_cook(const MaterialDescription& d) {
  const auto& p = d.parameters;
  JohnsonCookFlow flow;
  flow.A = p.at("yield_stress");
  flow.B = p.at("hardening_coefficient");
  flow.n = p.at("hardening_exponent");
  flow.C = p.at("strain_rate_coefficient");
  flow.m = p.at("thermal_softening_exponent");
  PlasticityConstants c = detail::constants(d);
  if (c.damage_enabled) c.damage.d5 = material_parameter(d, "damage_d5");
  c.softening = p.count("melting_temperature") != 0;
  if (c.softening) c.melting_temperature = p.at("melting_temperature");
  return detail::make_with_eos<Dim>("johnson_cook", c, flow, d);
}

template <int Dim>
std::unique_ptr<Material<Dim>> make_j2_plasticity(const MaterialDescription& d) {
  const auto& p = d.parameters;
  HardeningFlow flow;
  flow.yield_stress = p.at("yield_stress");
  flow.hardening_modulus = p.at("hardening_modulus");
  flow.saturation_stress = p.at("voce_saturation_stress");
  flow.saturation_rate = p.at("voce_exponent");
  return detail::make_with_eos<Dim>("j2_plasticity", detail::constants(d), flow, d);
}

}  // namespace mpm::plasticity
