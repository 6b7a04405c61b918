// `materials:` (docs/scene-reference.md, materials): each material's parameters checked against its model's
// spec (material_registry.hpp), defaults filled in.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "mpm/core/closest_name.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/spec_map.hpp"
#include "sections.hpp"

namespace mpm {

const std::vector<io::KeySpec>& material_keys() {
  static const std::vector<io::KeySpec> keys{
      {.name = "model",
       .type = io::KeyType::choice,
       .required = true,
       .description = "the material model; its parameters are the other keys of the entry (tables below)",
       .allowed_text = "a registered material model, see [Models](#models)",
       .fork_refusal = "the state layout of the model: the particles' state fields are the checkpoint's model's"},
      {.name = "failure",
       .type = io::KeyType::map,
       .absent = "never fails",
       .description = "when the material's particles fail and what they become (keys of materials.failure below)",
       .fork_refusal = "the particles' failure state (damage, erosion) comes from the checkpoint",
       .keys = failure_keys()},
  };
  return keys;
}

std::vector<io::ForkRule> material_fork_rules() {
  // Material::density() gives the particles their masses when the bodies are built; a restore keeps the
  // checkpoint's masses, so a new density would not take effect (and would disagree with them in the wave speed)
  constexpr std::string_view mass_parameter = "density";
  std::vector<io::ForkRule> rules;
  for (const auto& name : material_model_names()) {
    const MaterialModel& model = *find_material_model(name);
    for (const auto& p : material_parameters(model)) {
      const std::string pattern = "materials.*." + p.name;
      if (p.name == mass_parameter)
        rules.push_back({pattern, false, "the particles' masses come from the checkpoint (computed from it at t = 0)"});
      else if (std::none_of(rules.begin(), rules.end(), [&](const io::ForkRule& r) { return r.pattern == pattern; }))
        rules.push_back({pattern, true, ""});
    }
    for (auto& rule : io::fork_rules(model.keys, "materials.*")) rules.push_back(std::move(rule));
  }
  return rules;
}

namespace sections {
namespace {

/// The index of the word a choice parameter (ParameterSpec::choices) names.
double read_choice(const YamlReader& reader, const io::YamlValue& value, const ParameterSpec& p) {
  const std::string word = reader.string(value);
  const auto it = std::find(p.choices.begin(), p.choices.end(), word);
  if (it == p.choices.end())
    reader.fail(value, fmt::format("unknown {} '{}'{}; valid values: {}", p.name, word, did_you_mean(word, p.choices),
                                   fmt::join(p.choices, ", ")));
  return static_cast<double>(it - p.choices.begin());
}

MaterialDescription read_material(const YamlReader& reader, const YamlMap::Entry& entry) {
  MaterialDescription material;
  material.name = entry.key;
  material.where = reader.location(entry.key_mark);
  if (material.name.empty()) reader.fail(entry.key_mark, entry.value.path, "material name must not be empty");
  const io::SpecMap map(reader, entry.value, material_keys(), io::SpecMap::AllowLater{});
  const io::YamlValue model_key = map.required("model");
  material.model = reader.string(model_key);
  const MaterialModel* model = find_material_model(material.model);
  if (!model)
    reader.fail(model_key, fmt::format("unknown material model '{}'{}; valid models: {}", material.model,
                                       did_you_mean(material.model, material_model_names()),
                                       fmt::join(material_model_names(), ", ")));
  const std::vector<ParameterSpec> parameters = material_parameters(*model);
  std::vector<std::string> keys;
  keys.reserve(parameters.size());
  for (const auto& p : parameters) keys.push_back(p.name);
  for (const auto& k : model->keys) keys.push_back(k.name);
  map.allow(keys, "parameter", " for model " + material.model);
  for (const auto& p : parameters) {
    if (const auto value = map.map().find(p.name)) {
      material.parameters[p.name] =
          p.choices.empty() ? reader.number(*value, p.range, p.unit) : read_choice(reader, *value, p);
    } else if (p.default_value) {
      if (p.applies_with.empty()) material.parameters[p.name] = *p.default_value;  // else material_parameter()
    } else if (p.is_required()) {
      map.map().required(p.name, "parameter",
                         fmt::format(" of model {} ({}{})", material.model, p.description,
                                     p.unit.empty() || p.unit == "-" ? "" : ", " + p.unit));
    }
  }
  if (model->check)
    if (const auto error = model->check(material.parameters)) {
      if (const auto value = map.map().find(error->key)) reader.fail(*value, error->message);
      reader.fail(entry.key_mark, map.map().path_of(error->key), error->message);
    }
  if (model->read_keys) material.model_keys = model->read_keys(reader, map.map(), material);
  if (const auto failure = map.find("failure")) {
    material.failure_where = reader.location(failure->mark);
    material.failure = read_failure(reader, *failure, material, *model);
  }
  return material;
}

}  // namespace

std::map<std::string, MaterialDescription> read_materials(const YamlReader& reader, const io::YamlValue& value) {
  const YamlMap map = reader.map(value);
  if (map.entries().empty()) reader.fail(value, "at least one material is required");
  std::map<std::string, MaterialDescription> materials;
  for (const auto& entry : map.entries()) materials[entry.key] = read_material(reader, entry);
  return materials;
}

}  // namespace sections
}  // namespace mpm
