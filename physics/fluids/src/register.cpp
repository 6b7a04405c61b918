#include "mpm/fluids/register.hpp"

#include <limits>
#include <mutex>

#include "mpm/fluids/ideal_gas.hpp"
#include "mpm/fluids/output_fields.hpp"
#include "mpm/fluids/tait_fluid.hpp"
#include "mpm/material_batch.hpp"
#include "mpm/material_catalog.hpp"
#include "mpm/material_factory.hpp"

namespace mpm::fluids {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

ParameterSpec parameter(std::string name, std::string unit, std::string description, std::optional<double> value,
                        double lower, bool lower_inclusive) {
  ParameterSpec p;
  p.name = std::move(name);
  p.unit = std::move(unit);
  p.description = std::move(description);
  p.default_value = value;
  p.lower = lower;
  p.lower_inclusive = lower_inclusive;
  p.upper = inf;
  return p;
}

MaterialModelSpec newtonian_spec() {
  MaterialModelSpec s;
  s.model = "newtonian_fluid";
  s.description =
      "weakly compressible Newtonian fluid (review eqs 5.29-5.31): Tait EOS p = K [(rho/rho0)^gamma - 1], "
      "sigma = 2 mu dev(D) + zeta tr(D) I - p I, density from det F";
  s.parameters = {
      parameter("density", "kg/m^3", "reference density rho0", std::nullopt, 0, false),
      parameter("bulk_modulus", "Pa", "K of the Tait equation (may be reduced: weak compressibility)", std::nullopt, 0,
                false),
      parameter("eos_exponent", "-", "Tait exponent gamma (7 water, 1.4 air)", 7.0, 1, false),
      parameter("viscosity", "Pa s", "dynamic (shear) viscosity mu", 0.0, 0, true),
      parameter("bulk_viscosity", "Pa s", "bulk viscosity zeta = lambda + 2 mu/3 (0: Stokes condition)", 0.0, 0, true),
      parameter("density_tolerance", "-",
                "largest |rho/rho0 - 1| before the run warns that the bulk modulus is too small", 0.03, 0, false),
  };
  return s;
}

MaterialModelSpec ideal_gas_spec() {
  MaterialModelSpec s;
  s.model = "ideal_gas";
  s.description =
      "ideal gas (review eqs 5.32-5.35): p = (gamma - 1) rho e, internal energy per particle, artificial "
      "viscosity in compression";
  s.parameters = {
      parameter("density", "kg/m^3", "initial density rho0", std::nullopt, 0, false),
      parameter("initial_pressure", "Pa", "initial pressure p0 (sets e0 = p0 / ((gamma - 1) rho0))", std::nullopt, 0,
                false),
      parameter("gamma", "-", "ratio of specific heats", 1.4, 1, false),
      parameter("artificial_viscosity_linear", "-", "c_1 of eq. 5.35 (linear in tr D)", 0.0, 0, true),
      parameter("artificial_viscosity_quadratic", "-", "c_2 of eq. 5.35 (quadratic in tr D)", 0.0, 0, true),
  };
  return s;
}

}  // namespace

template <int Dim>
std::unique_ptr<Material<Dim>> make_newtonian_fluid(const MaterialDescription& d) {
  const auto& p = d.parameters;
  const TaitFluid::Params c{p.at("density"),   p.at("bulk_modulus"),   p.at("eos_exponent"),
                            p.at("viscosity"), p.at("bulk_viscosity"), p.at("density_tolerance")};
  return std::make_unique<MaterialBatch<Dim, TaitFluid>>(c);
}

template <int Dim>
std::unique_ptr<Material<Dim>> make_ideal_gas(const MaterialDescription& d) {
  const auto& p = d.parameters;
  IdealGasParams c;
  c.density = p.at("density");
  c.gamma = p.at("gamma");
  c.initial_pressure = p.at("initial_pressure");
  c.viscosity_linear = p.at("artificial_viscosity_linear");
  c.viscosity_quadratic = p.at("artificial_viscosity_quadratic");
  return std::make_unique<IdealGas<Dim>>(c);
}

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_material_model(newtonian_spec());
    register_material_factory("newtonian_fluid", &make_newtonian_fluid<1>, &make_newtonian_fluid<2>,
                              &make_newtonian_fluid<3>);
    register_material_model(ideal_gas_spec());
    register_material_factory("ideal_gas", &make_ideal_gas<1>, &make_ideal_gas<2>, &make_ideal_gas<3>);
    register_output_fields();
  });
}

template std::unique_ptr<Material<1>> make_newtonian_fluid<1>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_newtonian_fluid<2>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_newtonian_fluid<3>(const MaterialDescription&);
template std::unique_ptr<Material<1>> make_ideal_gas<1>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_ideal_gas<2>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_ideal_gas<3>(const MaterialDescription&);

}  // namespace mpm::fluids
