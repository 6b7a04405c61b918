#pragma once
// Builders of the plastic materials from validated scene parameters, instantiated once per dimension
// (make_plastic_material_{1,2,3}d.cpp, compiled in parallel).
#include <memory>

#include "mpm/materials/elastic_constants.hpp"
#include "mpm/plasticity/plastic_batch.hpp"
#include "mpm/plasticity/register.hpp"

namespace mpm::plasticity::detail {

inline Real get(const std::map<std::string, double>& p, const char* key, Real fallback) {
  const auto it = p.find(key);
  return it == p.end() ? fallback : it->second;
}

/// The constants every plastic model shares (parameter names: docs/scene-reference.md).
inline PlasticityConstants constants(const std::map<std::string, double>& p) {
  const ElasticConstants e = ElasticConstants::from_parameters(p);
  PlasticityConstants c;
  c.density = e.density;
  c.shear_modulus = e.mu;
  c.bulk_modulus = e.bulk;
  c.reference_strain_rate = get(p, "reference_strain_rate", 1);
  c.damage_enabled = p.count("damage_d1") != 0;
  c.damage.d1 = get(p, "damage_d1", 0);
  c.damage.d2 = get(p, "damage_d2", 0);
  c.damage.d3 = get(p, "damage_d3", 0);
  c.damage.d4 = get(p, "damage_d4", 0);
  c.damage.d5 = get(p, "damage_d5", 0);
  c.damage.evolution_factor = get(p, "damage_evolution_factor", 10);
  c.thermal = p.count("specific_heat") != 0;
  c.specific_heat = get(p, "specific_heat", 0);
  c.taylor_quinney = get(p, "taylor_quinney_coefficient", 0.9);
  c.room_temperature = get(p, "room_temperature", 293.15);
  c.thermal_expansion = get(p, "thermal_expansion", 0);
  c.softening = p.count("melting_temperature") != 0;
  c.melting_temperature = get(p, "melting_temperature", 0);
  c.viscosity_linear = get(p, "artificial_viscosity_linear", 0);
  c.viscosity_quadratic = get(p, "artificial_viscosity_quadratic", 0);
  return c;
}

template <int Dim, class Flow>
std::unique_ptr<Material<Dim>> make_with_eos(const char* key, const PlasticityConstants& c, const Flow& flow,
                                             const std::map<std::string, double>& p) {
  if (p.count("bulk_sound_speed")) {
    ElastoplasticParams<Flow, MieGruneisenEos> params;
    static_cast<PlasticityConstants&>(params) = c;
    params.flow = flow;
    params.eos = {c.density, p.at("bulk_sound_speed"), get(p, "hugoniot_slope", 0), get(p, "gruneisen_gamma", 0)};
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
  flow.C = detail::get(p, "strain_rate_coefficient", 0);
  flow.m = detail::get(p, "thermal_softening_exponent", 1);
  return detail::make_with_eos<Dim>("johnson_cook", detail::constants(p), flow, p);
}

template <int Dim>
std::unique_ptr<Material<Dim>> make_j2_plasticity(const MaterialDescription& d) {
  const auto& p = d.parameters;
  HardeningFlow flow;
  flow.yield_stress = p.at("yield_stress");
  flow.hardening_modulus = detail::get(p, "hardening_modulus", 0);
  flow.saturation_stress = detail::get(p, "voce_saturation_stress", 0);
  flow.saturation_rate = detail::get(p, "voce_exponent", 0);
  return detail::make_with_eos<Dim>("j2_plasticity", detail::constants(p), flow, p);
}

}  // namespace mpm::plasticity
