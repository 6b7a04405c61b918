#include "mpm/plasticity/register.hpp"

#include "hencky_j2_registration.hpp"

#include <fmt/format.h>

#include <mutex>

#include "mpm/materials/material_registry.hpp"
#include "mpm/plasticity/output_fields.hpp"

namespace mpm::plasticity {
namespace {

using io::Range;

ParameterSpec required(std::string name, std::string unit, Range range, std::string description) {
  return ParameterSpec::required(std::move(name), std::move(unit), range, std::move(description));
}
ParameterSpec with_default(std::string name, std::string unit, double value, Range range, std::string description) {
  return ParameterSpec::with_default(std::move(name), std::move(unit), value, range, std::move(description));
}
ParameterSpec optional(std::string name, std::string unit, Range range, std::string absent, std::string description) {
  return ParameterSpec::optional(std::move(name), std::move(unit), range, std::move(absent), std::move(description));
}

/// The elastic constants both models start with.
std::vector<ParameterSpec> elastic_parameters() {
  return {
      required("density", "kg/m^3", Range::above(0), "reference mass density rho0"),
      required("youngs_modulus", "Pa", Range::above(0), "Young's modulus E (shear modulus G = E / (2 (1 + nu)))"),
      required("poisson_ratio", "-", Range::open(-1, 0.5),
               "Poisson's ratio nu (bulk modulus K = E / (3 (1 - 2 nu)) of the linear EOS p = K (1 - det F))"),
  };
}

/// Parameters of both models after their flow stress: equation of state, damage, temperature, artificial
/// viscosity.
std::vector<ParameterSpec> shared_parameters() {
  return {
      optional("bulk_sound_speed", "m/s", Range::above(0), "absent: linear EOS",
               "c0 of the Mie-Gruneisen EOS (eq. B.9); selects it"),
      with_default("hugoniot_slope", "-", 0, Range::at_least(0),
                   "S of the linear Us-up Hugoniot Us = c0 + S up (Mie-Gruneisen; needs bulk_sound_speed)")
          .only_with("bulk_sound_speed"),
      with_default("gruneisen_gamma", "-", 0, Range::at_least(0),
                   "Gruneisen Gamma0 (Mie-Gruneisen; needs bulk_sound_speed)")
          .only_with("bulk_sound_speed"),
      with_default("reference_strain_rate", "1/s", 1, Range::above(0),
                   "rate0 normalising the plastic strain rate of the rate terms"),
      optional("damage_d1", "-", Range::any(), "absent: no damage",
               "Johnson-Cook damage D1 (eq. B.15); enables damage"),
      with_default("damage_d2", "-", 0, Range::any(), "Johnson-Cook damage D2 (needs damage_d1)")
          .only_with("damage_d1"),
      with_default("damage_d3", "-", 0, Range::any(),
                   "Johnson-Cook damage D3, the triaxiality exponent (needs damage_d1)")
          .only_with("damage_d1"),
      with_default("damage_d4", "-", 0, Range::any(), "Johnson-Cook damage D4, the strain-rate term (needs damage_d1)")
          .only_with("damage_d1"),
      with_default("damage_evolution_factor", "-", 10, Range::above(0), "k of D = k (D_init - 1) (eq. B.16)"),
      optional("specific_heat", "J/(kg K)", Range::above(0), "absent: no temperature",
               "specific heat c; enables the particle field temperature and adiabatic heating (eq. B.13)"),
      with_default("taylor_quinney_coefficient", "-", 0.9, Range::closed(0, 1),
                   "fraction chi of plastic work turned into heat (eq. B.13)"),
      with_default("room_temperature", "K", 293.15, Range::above(0), "reference (and initial) temperature T_r"),
      with_default("thermal_expansion", "1/K", 0, Range::any(),
                   "linear thermal expansion coefficient alpha: the EOS uses J exp(-3 alpha (T - T_r)) (needs "
                   "specific_heat)")
          .only_with("specific_heat"),
      with_default("artificial_viscosity_linear", "-", 0, Range::at_least(0),
                   "linear artificial bulk viscosity coefficient c_1 (in compression)"),
      with_default("artificial_viscosity_quadratic", "-", 0, Range::at_least(0),
                   "quadratic artificial bulk viscosity coefficient c_2 (in compression)"),
  };
}

/// elastic + flow stress + shared + the model's own extras, in the order the reference lists them.
std::vector<ParameterSpec> parameters(const std::vector<ParameterSpec>& flow, const std::vector<ParameterSpec>& extra) {
  std::vector<ParameterSpec> all = elastic_parameters();
  all.insert(all.end(), flow.begin(), flow.end());
  const auto shared = shared_parameters();
  all.insert(all.end(), shared.begin(), shared.end());
  all.insert(all.end(), extra.begin(), extra.end());
  return all;
}

std::optional<ParameterError> check_shared(const std::map<std::string, double>& values) {
  if (values.count("thermal_expansion") && !values.count("specific_heat"))
    return ParameterError{"thermal_expansion",
                          "thermal expansion needs the temperature, which is only tracked with specific_heat "
                          "(J/(kg K)); give specific_heat too"};
  for (const char* key : {"hugoniot_slope", "gruneisen_gamma"})
    if (values.count(key) && !values.count("bulk_sound_speed"))
      return ParameterError{key, fmt::format("{} belongs to the Mie-Gruneisen equation of state, which "
                                             "bulk_sound_speed (m/s) selects; give bulk_sound_speed too",
                                             key)};
  for (const char* key : {"damage_d2", "damage_d3", "damage_d4", "damage_d5"})
    if (values.count(key) && !values.count("damage_d1"))
      return ParameterError{key, fmt::format("{} is a Johnson-Cook damage constant, but damage is only enabled by "
                                             "damage_d1; give damage_d1 too",
                                             key)};
  return std::nullopt;
}

std::optional<ParameterError> check_johnson_cook(const std::map<std::string, double>& values) {
  if (auto error = check_shared(values)) return error;
  if (values.count("melting_temperature")) {
    if (!values.count("specific_heat"))
      return ParameterError{"melting_temperature",
                            "thermal softening needs the temperature, which is only tracked with specific_heat "
                            "(J/(kg K)); give specific_heat too"};
    if (!(values.at("melting_temperature") > values.at("room_temperature")))
      return ParameterError{"melting_temperature",
                            fmt::format("must exceed room_temperature ({} K), got {} K", values.at("room_temperature"),
                                        values.at("melting_temperature"))};
  }
  if (values.count("damage_d5") && !values.count("melting_temperature"))
    return ParameterError{"damage_d5",
                          "the temperature term D5 needs melting_temperature (T* = (T - T_r)/(T_m - T_r))"};
  return std::nullopt;
}

MaterialModel johnson_cook_model() {
  return {.key = "johnson_cook",
          .description =
              "Johnson-Cook elasto-plasticity (review App. B.3): J2 radial return in the un-rotated frame, "
              "flow stress [A + B eps_p^n][1 + C ln rate*][1 - T*^m], linear or Mie-Gruneisen EOS, optional "
              "Johnson-Cook damage and adiabatic heating",
          .parameters = parameters(
              {required("yield_stress", "Pa", Range::above(0), "Johnson-Cook A"),
               required("hardening_coefficient", "Pa", Range::at_least(0), "Johnson-Cook B"),
               required("hardening_exponent", "-", Range::above(0), "Johnson-Cook n"),
               with_default("strain_rate_coefficient", "-", 0, Range::at_least(0), "Johnson-Cook C"),
               with_default("thermal_softening_exponent", "-", 1, Range::above(0), "Johnson-Cook m")},
              {with_default("damage_d5", "-", 0, Range::any(),
                            "Johnson-Cook damage D5, the temperature term (needs damage_d1 and melting_temperature)")
                   .only_with("damage_d1"),
               optional("melting_temperature", "K", Range::above(0), "absent: no thermal softening",
                        "T_m of the thermal softening [1 - T*^m]; enables it (must exceed room_temperature; needs "
                        "specific_heat)")}),
          .check = check_johnson_cook,
          .make_1d = &make_johnson_cook<1>,
          .make_2d = &make_johnson_cook<2>,
          .make_3d = &make_johnson_cook<3>,
          .thermal_expansion = ThermalExpansion::in_update,
          .tracks_plastic_strain = true,
          .damage_enabled_by = "damage_d1"};
}

MaterialModel j2_model() {
  return {.key = "j2_plasticity",
          .description =
              "J2 (von Mises) elasto-plasticity (review App. B.3, Table 9): radial return in the un-rotated "
              "frame, flow stress sigma_y + H eps_p + Q (1 - exp(-b eps_p)) (perfectly plastic, linear or "
              "Voce hardening), linear or Mie-Gruneisen EOS, optional Johnson-Cook damage and adiabatic "
              "heating",
          .parameters = parameters(
              {required("yield_stress", "Pa", Range::above(0), "initial yield stress sigma_y"),
               with_default("hardening_modulus", "Pa", 0, Range::at_least(0), "linear hardening modulus H"),
               with_default("voce_saturation_stress", "Pa", 0, Range::at_least(0), "Voce saturation stress Q"),
               with_default("voce_exponent", "-", 0, Range::at_least(0), "Voce exponent b")},
              {}),
          .check = check_shared,
          .make_1d = &make_j2_plasticity<1>,
          .make_2d = &make_j2_plasticity<2>,
          .make_3d = &make_j2_plasticity<3>,
          .thermal_expansion = ThermalExpansion::in_update,
          .tracks_plastic_strain = true,
          .damage_enabled_by = "damage_d1"};
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_material_model(johnson_cook_model());
    register_material_model(j2_model());
    detail::register_hencky_j2();
    register_output_fields();
  });
}

}  // namespace mpm::plasticity
