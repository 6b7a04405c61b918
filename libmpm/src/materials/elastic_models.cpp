#include "elastic_models.hpp"

#include "mpm/materials/linear_elastic.hpp"
#include "mpm/materials/material_batch.hpp"
#include "mpm/materials/neo_hookean.hpp"

namespace mpm {
namespace {

using io::Range;

// Elastic constants shared by the core models (review App. B.1-B.2). Poisson's ratio is restricted to
// (-1, 0.5): 0.5 is incompressible and has no finite bulk modulus in these explicit models.
std::vector<ParameterSpec> elastic_parameters() {
  return {
      ParameterSpec::required("density", "kg/m^3", Range::above(0), "reference mass density rho0"),
      ParameterSpec::required("youngs_modulus", "Pa", Range::above(0), "Young's modulus E"),
      ParameterSpec::required("poisson_ratio", "-", Range::open(-1, 0.5), "Poisson's ratio nu"),
  };
}

template <int Dim, class Law>
std::unique_ptr<Material<Dim>> make_elastic(const MaterialDescription& d) {
  return std::make_unique<MaterialBatch<Dim, Law>>(ElasticConstants::from_parameters(d.parameters));
}

/// K0 of a laterally confined elastic column under its weight: no lateral strain, sigma_h = nu / (1 - nu) sigma_v
/// (docs/theory.md eq. 20.2).
double confined_k0(const std::map<std::string, double>& p) {
  return p.at("poisson_ratio") / (1 - p.at("poisson_ratio"));
}

template <class Law>
MaterialModel elastic_model(const char* description, ThermalExpansion expansion, bool takes_initial_stress) {
  return {.key = Law::key,
          .description = description,
          .parameters = elastic_parameters(),
          .make_1d = &make_elastic<1, Law>,
          .make_2d = &make_elastic<2, Law>,
          .make_3d = &make_elastic<3, Law>,
          .thermal_expansion = expansion,
          .takes_initial_stress = takes_initial_stress,
          .at_rest_coefficient = takes_initial_stress ? &confined_k0 : nullptr};
}

}  // namespace

std::vector<MaterialModel> elastic_material_models() {
  return {
      // thermal stress -3 K alpha (T - T0) I (eq. 5.26) from its isotropic constants, added by heat conduction
      elastic_model<LinearElastic>(
          "Isotropic linear elasticity, incremental (hypoelastic) form B.5 with the Jaumann rate",
          ThermalExpansion::by_heat_conduction, /*takes_initial_stress=*/true),
      elastic_model<NeoHookean>("Compressible Neo-Hookean hyperelasticity, eq. B.6-B.7 (Bonet & Wood)",
                                ThermalExpansion::unsupported, /*takes_initial_stress=*/false),
  };
}

}  // namespace mpm
