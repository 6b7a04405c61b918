#pragma once
/// \file material_catalog.hpp
/// What the scene loader needs to know about material models: their YAML keys, their parameters with
/// units and admissible ranges. The catalog is filled by the core (linear_elastic, neo_hookean) and by
/// each optional module through register_material_model() when it is compiled in.

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mpm {

/// One named parameter of a material model.
struct ParameterSpec {
  std::string name;  ///< YAML key, snake_case, e.g. "youngs_modulus"
  std::string unit;  ///< SI unit, e.g. "Pa"
  std::string description;
  std::optional<double> default_value;  ///< empty: required
  double lower = -std::numeric_limits<double>::infinity();
  bool lower_inclusive = true;
  double upper = std::numeric_limits<double>::infinity();
  bool upper_inclusive = true;
};

/// A material model as seen by the scene: YAML key, description, parameters.
struct MaterialModelSpec {
  std::string model;  ///< e.g. "linear_elastic"
  std::string description;
  std::vector<ParameterSpec> parameters;
};

/// The model with this key, or nullptr.
const MaterialModelSpec* find_material_model(std::string_view model);
/// Keys of all registered models, sorted (for "valid models are: ..." messages).
std::vector<std::string> material_model_names();

}  // namespace mpm
