#include "mpm/plasticity/register.hpp"

#include "hencky_j2_registration.hpp"

#include <fmt/format.h>

#include <mutex>

#include "mpm/material_catalog.hpp"
#include "mpm/material_factory.hpp"

namespace mpm::plasticity {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

ParameterSpec required(std::string name, std::string unit, std::string description, double lower = -inf,
                       bool lower_inclusive = true, double upper = inf, bool upper_inclusive = true) {
  return {std::move(name), std::move(unit), std::move(description), std::nullopt, lower,
          lower_inclusive, upper,           upper_inclusive};
}
ParameterSpec with_default(std::string name, std::string unit, std::string description, double value,
                           double lower = -inf, bool lower_inclusive = true, double upper = inf,
                           bool upper_inclusive = true) {
  return {std::move(name), std::move(unit), std::move(description), value, lower,
          lower_inclusive, upper,           upper_inclusive};
}
ParameterSpec optional(std::string name, std::string unit, std::string description, double lower = -inf,
                       bool lower_inclusive = true, double upper = inf, bool upper_inclusive = true) {
  ParameterSpec p = required(std::move(name), std::move(unit), std::move(description), lower, lower_inclusive, upper,
                             upper_inclusive);
  p.optional = true;
  return p;
}

/// Parameters of both models: elasticity, equation of state, damage, temperature, artificial viscosity.
std::vector<ParameterSpec> shared_parameters(bool johnson_cook) {
  std::vector<ParameterSpec> p = {
      required("density", "kg/m^3", "reference mass density rho0", 0.0, false),
      required("youngs_modulus", "Pa", "Young's modulus E (shear modulus G = E / (2 (1 + nu)))", 0.0, false),
      required("poisson_ratio", "-", "Poisson's ratio nu (bulk modulus K = E / (3 (1 - 2 nu)) of the linear EOS)", -1.0,
               false, 0.5, false),
      optional("bulk_sound_speed", "m/s", "c0 of the Mie-Gruneisen EOS (eq. B.9); selects it", 0.0, false),
      optional("hugoniot_slope", "-", "S of the linear Us-up Hugoniot Us = c0 + S up (Mie-Gruneisen)", 0.0, true),
      optional("gruneisen_gamma", "-", "Gruneisen Gamma0 (Mie-Gruneisen)", 0.0, true),
      with_default("reference_strain_rate", "1/s", "rate0 normalising the plastic strain rate", 1.0, 0.0, false),
      optional("damage_d1", "-", "Johnson-Cook damage D1 (eq. B.15); enables damage"),
      optional("damage_d2", "-", "Johnson-Cook damage D2"),
      optional("damage_d3", "-", "Johnson-Cook damage D3 (triaxiality exponent)"),
      optional("damage_d4", "-", "Johnson-Cook damage D4 (strain-rate term)"),
      with_default("damage_evolution_factor", "-", "k of D = k (D_init - 1) (eq. B.16)", 10.0, 0.0, false),
      optional("specific_heat", "J/(kg K)", "specific heat c; enables the temperature field and adiabatic heating", 0.0,
               false),
      with_default("taylor_quinney_coefficient", "-", "fraction chi of plastic work turned into heat (eq. B.13)", 0.9,
                   0.0, true, 1.0, true),
      with_default("room_temperature", "K", "reference (and initial) temperature T_r", 293.15, 0.0, false),
      optional("thermal_expansion", "1/K",
               "linear thermal expansion coefficient alpha: the EOS uses J exp(-3 alpha (T - T_r)) (needs "
               "specific_heat)"),
      with_default("artificial_viscosity_linear", "-", "linear artificial bulk viscosity coefficient c_1", 0.0, 0.0),
      with_default("artificial_viscosity_quadratic", "-", "quadratic artificial bulk viscosity coefficient c_2", 0.0,
                   0.0),
  };
  if (johnson_cook) {
    p.push_back(optional("damage_d5", "-", "Johnson-Cook damage D5 (temperature term; needs melting_temperature)"));
    p.push_back(optional("melting_temperature", "K",
                         "T_m of the thermal softening [1 - T*^m]; enables it (needs specific_heat)", 0.0, false));
  }
  return p;
}

std::optional<ParameterError> check_shared(const std::map<std::string, double>& p) {
  if (p.count("thermal_expansion") && !p.count("specific_heat"))
    return ParameterError{"thermal_expansion",
                          "thermal expansion needs the temperature, which is only tracked with specific_heat "
                          "(J/(kg K)); give specific_heat too"};
  for (const char* key : {"hugoniot_slope", "gruneisen_gamma"})
    if (p.count(key) && !p.count("bulk_sound_speed"))
      return ParameterError{key, fmt::format("{} belongs to the Mie-Gruneisen equation of state, which "
                                             "bulk_sound_speed (m/s) selects; give bulk_sound_speed too",
                                             key)};
  for (const char* key : {"damage_d2", "damage_d3", "damage_d4", "damage_d5"})
    if (p.count(key) && !p.count("damage_d1"))
      return ParameterError{key, fmt::format("{} is a Johnson-Cook damage constant, but damage is only enabled by "
                                             "damage_d1; give damage_d1 too",
                                             key)};
  return std::nullopt;
}

std::optional<ParameterError> check_johnson_cook(const std::map<std::string, double>& p) {
  if (auto e = check_shared(p)) return e;
  if (p.count("melting_temperature")) {
    if (!p.count("specific_heat"))
      return ParameterError{"melting_temperature",
                            "thermal softening needs the temperature, which is only tracked with specific_heat "
                            "(J/(kg K)); give specific_heat too"};
    if (!(p.at("melting_temperature") > p.at("room_temperature")))
      return ParameterError{"melting_temperature", fmt::format("must exceed room_temperature ({} K), got {} K",
                                                               p.at("room_temperature"), p.at("melting_temperature"))};
  }
  if (p.count("damage_d5") && !p.count("melting_temperature"))
    return ParameterError{"damage_d5",
                          "the temperature term D5 needs melting_temperature (T* = (T - T_r)/(T_m - T_r))"};
  return std::nullopt;
}

MaterialModelSpec johnson_cook_spec() {
  MaterialModelSpec s;
  s.model = "johnson_cook";
  s.description =
      "Johnson-Cook elasto-plasticity (review App. B.3): J2 radial return in the un-rotated frame, flow stress "
      "[A + B eps_p^n][1 + C ln rate*][1 - T*^m], linear or Mie-Gruneisen EOS, optional Johnson-Cook damage and "
      "adiabatic heating";
  s.parameters = shared_parameters(true);
  s.parameters.insert(s.parameters.begin() + 3,
                      {required("yield_stress", "Pa", "Johnson-Cook A", 0.0, false),
                       required("hardening_coefficient", "Pa", "Johnson-Cook B", 0.0, true),
                       required("hardening_exponent", "-", "Johnson-Cook n", 0.0, false),
                       with_default("strain_rate_coefficient", "-", "Johnson-Cook C", 0.0, 0.0, true),
                       with_default("thermal_softening_exponent", "-", "Johnson-Cook m", 1.0, 0.0, false)});
  s.check = check_johnson_cook;
  return s;
}

MaterialModelSpec j2_spec() {
  MaterialModelSpec s;
  s.model = "j2_plasticity";
  s.description =
      "J2 (von Mises) elasto-plasticity (review App. B.3, Table 9): radial return in the un-rotated frame, flow "
      "stress sigma_y + H eps_p + Q (1 - exp(-b eps_p)) (perfectly plastic, linear or Voce hardening), linear or "
      "Mie-Gruneisen EOS, optional Johnson-Cook damage and adiabatic heating";
  s.parameters = shared_parameters(false);
  s.parameters.insert(s.parameters.begin() + 3,
                      {required("yield_stress", "Pa", "initial yield stress sigma_y", 0.0, false),
                       with_default("hardening_modulus", "Pa", "linear hardening modulus H", 0.0, 0.0, true),
                       with_default("voce_saturation_stress", "Pa", "Voce saturation stress Q", 0.0, 0.0, true),
                       with_default("voce_exponent", "-", "Voce exponent b", 0.0, 0.0, true)});
  s.check = check_shared;
  return s;
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_material_model(johnson_cook_spec());
    register_material_factory("johnson_cook", &make_johnson_cook<1>, &make_johnson_cook<2>, &make_johnson_cook<3>);
    register_material_model(j2_spec());
    register_material_factory("j2_plasticity", &make_j2_plasticity<1>, &make_j2_plasticity<2>, &make_j2_plasticity<3>);
    detail::register_hencky_j2();
  });
}

}  // namespace mpm::plasticity
