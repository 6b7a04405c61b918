#pragma once
/// \file material_registry.hpp
/// The one place a material model is declared: its YAML key, its parameters (unit, admissible range,
/// default, description) and its builders for 1, 2 and 3 dimensions, given together to one
/// register_material_model() call. The core registers linear_elastic and neo_hookean this way
/// (src/materials/elastic_models.cpp), every optional module its own models from its register_module().
/// The scene loader checks the parameters against the specs and fills in the defaults, so a builder reads
/// every value it needs with .at(), without fallbacks; the parameter tables of docs/scene-reference.md are
/// generated from the same specs (material_reference.hpp).

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mpm/core/range.hpp"
#include "mpm/materials/material.hpp"
#include "mpm/scene/key_spec.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm {

namespace io {
class YamlReader;
class YamlMap;
}  // namespace io

/// One named parameter of a material model: required, with a default, or optional (omitting it switches a
/// feature off; it is then absent from MaterialDescription::parameters).
struct ParameterSpec {
  std::string name;                     ///< YAML key, snake_case, e.g. "youngs_modulus"
  std::string unit;                     ///< SI unit, e.g. "Pa"; "-" when dimensionless
  io::Range range;                      ///< admissible values
  std::optional<double> default_value;  ///< filled in by the loader when the scene omits the parameter
  /// Optional parameters only: what omitting it means, as the scene reference shows it in the Default column
  /// (e.g. "absent: no damage"). Empty for a required parameter or one with a default.
  std::string absent;
  std::string description;  ///< meaning and symbol; also part of the "missing required parameter" message
  /// With a default: the optional parameter whose feature this one belongs to (e.g. "bulk_sound_speed" for the
  /// Mie-Gruneisen constants). The loader then leaves it absent unless the scene gives it (so that the model's
  /// check can refuse it without its feature), and the maker reads it with material_parameter(), which falls
  /// back to this default. Empty: the loader fills the default in.
  std::string applies_with;
  /// A parameter that names one of a few choices (e.g. cone_matching: outer_cone): the scene gives one of these words
  /// and the model reads its index (0, 1, ...) as the value; empty for a number.
  std::vector<std::string> choices;

  /// A parameter the scene must give.
  static ParameterSpec required(std::string name, std::string unit, io::Range range, std::string description);
  /// A parameter that takes `value` when omitted.
  static ParameterSpec with_default(std::string name, std::string unit, double value, io::Range range,
                                    std::string description);
  /// A parameter that may be omitted, meaning `absent`.
  static ParameterSpec optional(std::string name, std::string unit, io::Range range, std::string absent,
                                std::string description);

  /// A parameter that names one of `choices`, the one of index `default_index` when omitted; the value the model
  /// reads is the index of the choice.
  static ParameterSpec choice(std::string name, std::vector<std::string> choices, int default_index,
                              std::string description);

  /// This spec as a part of the feature `parameter` switches on (see applies_with).
  ParameterSpec only_with(std::string parameter) const;

  bool is_required() const { return !default_value && absent.empty(); }
  bool operator==(const ParameterSpec&) const = default;
};

/// A problem with a combination of parameters, found by MaterialModel::check: the key to report it at (a
/// parameter name; reported at the material when that parameter was not given) and the message.
struct ParameterError {
  std::string key;
  std::string message;
};

/// Checks the parameters together: every one in its range, defaults filled in (optional ones and those of a
/// feature, ParameterSpec::applies_with, only when given).
using ParameterCheck = std::function<std::optional<ParameterError>(const std::map<std::string, double>& values)>;

/// Builds the model from a validated description (every parameter with a default present).
template <int Dim>
using MaterialMaker = std::unique_ptr<Material<Dim>> (*)(const MaterialDescription&);

/// Reads a model's keys that are not numbers (MaterialModel::keys) from the material's map, after its numbers
/// (`material.parameters`, checked and completed); the result is stored in MaterialDescription::model_keys. Throws
/// SceneError naming file, line and key (through `reader`).
using MaterialKeysReader = std::any (*)(const io::YamlReader& reader, const io::YamlMap& map,
                                        const MaterialDescription& material);

/// How thermal expansion (the common parameter `thermal_expansion`, eq. 5.26) enters a model's stress.
enum class ThermalExpansion {
  unsupported,         ///< not at all: a scene that gives thermal_expansion is refused
  by_heat_conduction,  ///< the heat conduction module's thermal stress, from youngs_modulus and poisson_ratio
  in_update,           ///< the model's own update, from the temperature field (also without a thermal: section)
};

/// What a model's matter is: the plausibility warnings hold its density to that kind's range (apps/plausibility.hpp).
enum class MaterialPhase {
  solid,   ///< elastic and elastic-plastic models
  liquid,  ///< a weakly compressible fluid
  gas,     ///< an ideal gas
  rigid,   ///< a rigid body: its density only gives its particles a mass
};

/// A material model: everything the loader, the builder and the scene reference know about it, and its traits:
/// what the modules that couple to a material ask of it instead of its key.
struct MaterialModel {
  std::string key;  ///< the scene's `model:`, e.g. "linear_elastic"
  std::string description;
  std::vector<ParameterSpec> parameters;  ///< the model's own, in the order the reference lists them
  ParameterCheck check = {};              ///< optional
  MaterialMaker<1> make_1d = nullptr;
  MaterialMaker<2> make_2d = nullptr;
  MaterialMaker<3> make_3d = nullptr;
  ThermalExpansion thermal_expansion = ThermalExpansion::unsupported;  ///< asked by heat conduction (thermal)
  /// Gives the algorithmic stress the implicit scheme solves with (ref. 003, eqs. 81-83, 90): a trial update without
  /// committing state, and its commit. Asked by `scheme: implicit`.
  bool implicit_stress = false;
  /// Keeps an equivalent plastic strain (output field `plastic_strain`): the failure criterion `plastic_strain` is
  /// refused for a model without it.
  bool tracks_plastic_strain = false;
  /// The parameter whose presence gives the model Johnson-Cook damage (output field `damage`, e.g. "damage_d1");
  /// empty: no damage. The failure criterion `damage` is refused for a material without it.
  std::string damage_enabled_by{};
  /// Its stress is its state, updated incrementally (a hypoelastic law): an initial stress (a set's
  /// `initial_stress`) is where it starts. A model whose stress follows from F or J (hyperelastic, fluids, an
  /// equation of state for the pressure) has no place for one and refuses it.
  bool takes_initial_stress = false;
  /// The coefficient of earth pressure at rest K0 = sigma_h / sigma_v of a geostatic initial stress (a condition's
  /// `initial_stress: geostatic` without `k0`), from the validated parameters: Jaky's 1 - sin(phi) for a frictional
  /// model, nu / (1 - nu) (no lateral strain) for an elastic one (docs/theory.md eq. 20.2). Null: the model gives
  /// none, and a geostatic stress on it needs `k0`. Only for models that take an initial stress.
  std::function<double(const std::map<std::string, double>& values)> at_rest_coefficient = nullptr;
  /// The kind of matter it describes (for the plausibility of its density).
  MaterialPhase phase = MaterialPhase::solid;
  /// Keys of the model whose values are not numbers (a file name, a list, a word), for the loader (allowed keys) and
  /// the reference; read by `read_keys`. Empty for nearly every model (user_material has `library`, `properties`, ...).
  std::vector<io::KeySpec> keys{};
  MaterialKeysReader read_keys = nullptr;  ///< reads `keys`; required when `keys` is not empty
};

/// Adds a model (or replaces the one with the same key). Call before loading scenes; the optional modules'
/// models are registered by the generated call mpm::app::register_modules().
void register_material_model(MaterialModel model);
/// The model with this key, or nullptr.
const MaterialModel* find_material_model(std::string_view key);
/// Keys of all registered models, sorted (for "valid models: ..." messages).
std::vector<std::string> material_model_names();
/// Keys of the registered models for which `accept(model)` is true, sorted, as "a, b and c" (for refusals that
/// say which models would do).
std::string material_model_names_where(const std::function<bool(const MaterialModel&)>& accept);

/// Adds parameters to every model, registered or to come, that does not declare one of that name itself (an
/// optional module's per-material keys, e.g. thermal_conductivity). The module that registers them reads them
/// from MaterialDescription::parameters; the models ignore them.
void register_common_material_parameters(const std::vector<ParameterSpec>& specs);
/// The parameters registered with register_common_material_parameters(), in registration order.
const std::vector<ParameterSpec>& common_material_parameters();
/// What a scene may give for `model`: its own parameters, then the common ones it does not declare.
std::vector<ParameterSpec> material_parameters(const MaterialModel& model);

/// Parameter `name` of a validated material: its value, or for a parameter the loader leaves absent
/// (ParameterSpec::applies_with) its spec's default. Throws std::out_of_range when it has neither.
double material_parameter(const MaterialDescription& description, std::string_view name);

/// Builds the material of `description` with its model's maker. Throws std::invalid_argument for an unknown
/// model (the scene loader has normally caught it).
template <int Dim>
std::unique_ptr<Material<Dim>> make_material(const MaterialDescription& description);

}  // namespace mpm
