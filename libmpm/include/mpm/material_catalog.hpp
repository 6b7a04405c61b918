#pragma once
/// \file material_catalog.hpp
/// What the scene loader needs to know about material models: their YAML keys, their parameters with
/// units and admissible ranges. The catalog is filled by the core (linear_elastic, neo_hookean) and by
/// each optional module through register_material_model() when it is compiled in.

#include <functional>
#include <limits>
#include <map>
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
  /// With no default: true = may be omitted, and is then absent from MaterialDescription::parameters
  /// (the model switches a feature off, e.g. no damage without damage_d1); false = required.
  bool optional = false;
};

/// A problem with a combination of parameters, found by MaterialModelSpec::check: the key to report it
/// at (a parameter name; reported at the material when that parameter was not given) and the message.
struct ParameterError {
  std::string key;
  std::string message;
};

/// A material model as seen by the scene: YAML key, description, parameters.
struct MaterialModelSpec {
  std::string model;  ///< e.g. "linear_elastic"
  std::string description;
  std::vector<ParameterSpec> parameters;
  /// Optional check of the parameters together (each already in its range; defaults filled in).
  std::function<std::optional<ParameterError>(const std::map<std::string, double>&)> check = {};
};

/// The model with this key, or nullptr.
const MaterialModelSpec* find_material_model(std::string_view model);
/// Keys of all registered models, sorted (for "valid models are: ..." messages).
std::vector<std::string> material_model_names();
/// Adds a model of an optional module (or replaces the one with the same key). Call before loading
/// scenes; modules are registered by the generated call mpm::app::register_modules().
void register_material_model(MaterialModelSpec spec);
/// Adds parameters to every model, registered or to come, that does not declare one of that name itself
/// (an optional module's per-material keys, e.g. thermal_conductivity). The module that registers them reads
/// them from MaterialDescription::parameters; the models ignore them.
void register_common_material_parameters(const std::vector<ParameterSpec>& specs);

}  // namespace mpm
