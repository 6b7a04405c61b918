#include "mpm/material_catalog.hpp"

#include <algorithm>

namespace mpm {
namespace {

// Elastic constants shared by the core models (review App. B.1-B.2). Poisson's ratio is restricted to
// (-1, 0.5): 0.5 is incompressible and has no finite bulk modulus in these explicit models.
std::vector<ParameterSpec> elastic_parameters() {
  return {
      {"density", "kg/m^3", "reference mass density rho0", std::nullopt, 0.0, false},
      {"youngs_modulus", "Pa", "Young's modulus E", std::nullopt, 0.0, false},
      {"poisson_ratio", "-", "Poisson's ratio nu", std::nullopt, -1.0, false, 0.5, false},
  };
}

std::vector<MaterialModelSpec>& catalog() {
  static std::vector<MaterialModelSpec> models = {
      {"linear_elastic", "Isotropic linear elasticity, incremental (hypoelastic) form B.5 with the Jaumann rate",
       elastic_parameters()},
      {"neo_hookean", "Compressible Neo-Hookean hyperelasticity, eq. B.6-B.7 (Bonet & Wood)", elastic_parameters()},
  };
  return models;
}

/// Parameters that an optional module adds to every model (the thermal module: conductivity, expansion).
std::vector<ParameterSpec>& common_parameters() {
  static std::vector<ParameterSpec> specs;
  return specs;
}

/// Appends the common parameters that `spec` does not declare itself.
void add_common(MaterialModelSpec& spec) {
  for (const auto& c : common_parameters())
    if (std::none_of(spec.parameters.begin(), spec.parameters.end(),
                     [&](const ParameterSpec& p) { return p.name == c.name; }))
      spec.parameters.push_back(c);
}

}  // namespace

const MaterialModelSpec* find_material_model(std::string_view model) {
  for (const auto& m : catalog())
    if (m.model == model) return &m;
  return nullptr;
}

void register_material_model(MaterialModelSpec spec) {
  add_common(spec);
  for (auto& m : catalog())
    if (m.model == spec.model) {
      m = std::move(spec);
      return;
    }
  catalog().push_back(std::move(spec));
}

void register_common_material_parameters(const std::vector<ParameterSpec>& specs) {
  for (const auto& s : specs) {
    auto& common = common_parameters();
    if (std::none_of(common.begin(), common.end(), [&](const ParameterSpec& c) { return c.name == s.name; }))
      common.push_back(s);
  }
  for (auto& m : catalog()) add_common(m);
}

std::vector<std::string> material_model_names() {
  std::vector<std::string> names;
  for (const auto& m : catalog()) names.push_back(m.model);
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace mpm
