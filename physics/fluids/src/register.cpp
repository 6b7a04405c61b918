#include "mpm/fluids/register.hpp"

#include <limits>
#include <mutex>

#include "mpm/fluids/ideal_gas.hpp"
#include "mpm/fluids/incompressible_fluid.hpp"
#include "mpm/fluids/output_fields.hpp"
#include "mpm/fluids/tait_fluid.hpp"
#include "mpm/materials/material_batch.hpp"
#include "mpm/materials/material_registry.hpp"
#include "pressure_projection_module.hpp"
#include "volume_smoothing_module.hpp"

namespace mpm::fluids {
namespace {

using io::Range;

std::vector<ParameterSpec> newtonian_parameters() {
  return {
      ParameterSpec::required("density", "kg/m^3", Range::above(0), "reference density rho0"),
      ParameterSpec::required("bulk_modulus", "Pa", Range::above(0),
                              "K of the Tait equation (may be reduced below the physical value to raise the time "
                              "step: weak compressibility)"),
      ParameterSpec::with_default("eos_exponent", "-", 7, Range::above(1), "Tait exponent gamma (7 water, 1.4 air)"),
      ParameterSpec::with_default("viscosity", "Pa s", 0, Range::at_least(0), "dynamic (shear) viscosity mu"),
      ParameterSpec::with_default("bulk_viscosity", "Pa s", 0, Range::at_least(0),
                                  "bulk viscosity zeta = lambda + 2 mu/3 (0: Stokes condition)"),
      ParameterSpec::with_default("density_tolerance", "-", 0.03, Range::above(0),
                                  "largest abs(rho/rho0 - 1) before `mpm run` warns (once per body) that the bulk "
                                  "modulus is too small for the flow"),
      ParameterSpec::optional("cavitation_pressure", "Pa",
                              Range{-std::numeric_limits<double>::infinity(), true, 0, true}, "absent: no limit",
                              "p_c: the pressure never falls below it, p = max(K [(rho/rho0)^gamma - 1], p_c) (0: "
                              "water that cannot hold tension, a free surface separates; the density warning then "
                              "only watches compression)"),
      ParameterSpec::with_default("volumetric_deformation", "-", 0, Range::closed(0, 1),
                                  "1: F keeps only its volume, F = J^(1/dim) I after every step (the law reads J "
                                  "alone); 0: the full F (the cpGIMP domains follow its stretch), reset to its volume "
                                  "only for a particle so distorted that det F would be round-off (eps |F|^dim > "
                                  "1e-8 J: in a splash F's entries grow without bound)"),
      ParameterSpec::with_default(
          smoothing_key, "-", 0, Range::closed(0, 1),
          "1: the pressure reads the node-averaged volume ratio, J mapped to the nodes by mass "
          "and interpolated back with hats before every stress update (docs/theory.md eq. "
          "PS.1; the stored energy it removes is summed in energy.csv's `smoothed_energy`); 0: each "
          "particle's own J. Explicit musl, usl and usf only"),
  };
}

std::vector<ParameterSpec> ideal_gas_parameters() {
  return {
      ParameterSpec::required("density", "kg/m^3", Range::above(0), "initial density rho0"),
      ParameterSpec::required("initial_pressure", "Pa", Range::above(0),
                              "initial pressure p0 (sets e0 = p0 / ((gamma - 1) rho0))"),
      ParameterSpec::with_default("gamma", "-", 1.4, Range::above(1), "ratio of specific heats"),
      ParameterSpec::with_default("artificial_viscosity_linear", "-", 0, Range::at_least(0),
                                  "c_1 of eq. 5.35 (linear in tr D)"),
      ParameterSpec::with_default("artificial_viscosity_quadratic", "-", 0, Range::at_least(0),
                                  "c_2 of eq. 5.35 (quadratic in tr D)"),
  };
}

MaterialModel newtonian_model() {
  return {.key = "newtonian_fluid",
          .description =
              "weakly compressible Newtonian fluid (review eqs 5.29-5.31): Tait EOS p = K [(rho/rho0)^gamma "
              "- 1], sigma = 2 mu dev(D) + zeta tr(D) I - p I, density from det F",
          .parameters = newtonian_parameters(),
          .check = [](const std::map<std::string, double>& p) -> std::optional<ParameterError> {
            if (const double v = p.at("volumetric_deformation"); v != 0 && v != 1)
              return ParameterError{"volumetric_deformation", "must be 0 (the full F) or 1 (its volume only)"};
            if (const double v = p.at(smoothing_key); v != 0 && v != 1)
              return ParameterError{smoothing_key, "must be 0 (each particle's J) or 1 (the node-averaged J)"};
            return std::nullopt;
          },
          .make_1d = &make_newtonian_fluid<1>,
          .make_2d = &make_newtonian_fluid<2>,
          .make_3d = &make_newtonian_fluid<3>,
          .phase = MaterialPhase::liquid};
}

std::vector<ParameterSpec> incompressible_parameters() {
  return {
      ParameterSpec::required("density", "kg/m^3", Range::above(0), "rho, constant"),
      ParameterSpec::with_default("viscosity", "Pa s", 0, Range::at_least(0), "dynamic (shear) viscosity mu"),
      ParameterSpec::with_default("projection_tolerance", "-", 1e-8, Range{0, false, 1e-2, true},
                                  "relative residual |A p - b| / |b| at which the conjugate gradients of the pressure "
                                  "projection stop (docs/theory.md eq. 21.2; with several incompressible "
                                  "materials the smallest)"),
      ParameterSpec::with_default("projection_iterations", "-", 10000, Range::at_least(1),
                                  "most conjugate-gradient iterations of one projection (with several materials "
                                  "the largest; about 200 with 40 x 80 fluid cells); a solve that stops short of "
                                  "projection_tolerance stops the run with a message"),
  };
}

MaterialModel incompressible_model() {
  return {.key = IncompressibleFluid::key,
          .description =
              "incompressible Newtonian fluid (docs/theory.md §21): sigma = 2 mu dev(D) - p I with the pressure "
              "from a projection of the grid velocity onto div v = 0 each step (no sound speed: the time step follows "
              "the flow); explicit musl, usl, usf in 2D and 3D, one process",
          .parameters = incompressible_parameters(),
          .make_1d = &make_incompressible_fluid<1>,
          .make_2d = &make_incompressible_fluid<2>,
          .make_3d = &make_incompressible_fluid<3>,
          .phase = MaterialPhase::liquid};
}

MaterialModel ideal_gas_model() {
  return {.key = "ideal_gas",
          .description =
              "ideal gas (review eqs 5.32-5.35): p = (gamma - 1) rho e, internal energy per particle, "
              "artificial viscosity in compression",
          .parameters = ideal_gas_parameters(),
          .make_1d = &make_ideal_gas<1>,
          .make_2d = &make_ideal_gas<2>,
          .make_3d = &make_ideal_gas<3>,
          .phase = MaterialPhase::gas};
}

}  // namespace

template <int Dim>
std::unique_ptr<Material<Dim>> make_newtonian_fluid(const MaterialDescription& d) {
  const auto& p = d.parameters;
  TaitFluid::Params c{p.at("density"),   p.at("bulk_modulus"),   p.at("eos_exponent"),
                      p.at("viscosity"), p.at("bulk_viscosity"), p.at("density_tolerance")};
  if (const auto it = p.find("cavitation_pressure"); it != p.end()) c.cavitation_pressure = it->second;
  c.volumetric_deformation = p.at("volumetric_deformation") == 1;
  return std::make_unique<MaterialBatch<Dim, TaitFluid>>(c);
}

template <int Dim>
std::unique_ptr<Material<Dim>> make_incompressible_fluid(const MaterialDescription& d) {
  return std::make_unique<MaterialBatch<Dim, IncompressibleFluid>>(
      IncompressibleFluid::Params{d.parameters.at("density"), d.parameters.at("viscosity")});
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
    register_material_model(newtonian_model());
    register_material_model(ideal_gas_model());
    register_material_model(incompressible_model());
    register_output_fields();
    register_volume_smoothing();
    register_pressure_projection();
  });
}

template std::unique_ptr<Material<1>> make_newtonian_fluid<1>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_newtonian_fluid<2>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_newtonian_fluid<3>(const MaterialDescription&);
template std::unique_ptr<Material<1>> make_incompressible_fluid<1>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_incompressible_fluid<2>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_incompressible_fluid<3>(const MaterialDescription&);
template std::unique_ptr<Material<1>> make_ideal_gas<1>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_ideal_gas<2>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_ideal_gas<3>(const MaterialDescription&);

}  // namespace mpm::fluids
