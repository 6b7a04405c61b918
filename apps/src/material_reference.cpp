#include "mpm/app/material_reference.hpp"
#include "markdown_cell.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "mpm/materials/material_registry.hpp"

namespace mpm {
namespace {

std::string default_cell(const ParameterSpec& p) {
  if (!p.choices.empty() && p.default_value) return p.choices.at(static_cast<std::size_t>(*p.default_value));
  if (p.default_value && !p.applies_with.empty())
    return fmt::format("{} (with `{}`)", *p.default_value, p.applies_with);
  if (p.default_value) return fmt::format("{}", *p.default_value);
  if (!p.absent.empty()) return p.absent;
  return "required";
}

std::string row(const ParameterSpec& p) {
  // a choice parameter: its words, not their indices
  const std::string allowed = p.choices.empty() ? p.range.describe() : fmt::format("{}", fmt::join(p.choices, ", "));
  return fmt::format("`{}` | {} | {} | {} | {} |\n", p.name, markdown_cell(p.unit), markdown_cell(default_cell(p)),
                     markdown_cell(allowed), markdown_cell(p.description));
}

/// A model's key that is not a number (MaterialModel::keys), as a row of the same table.
std::string row(const io::KeySpec& k) {
  return fmt::format("`{}` | {} | {} | {} | {} |\n", k.name, markdown_cell(k.unit.empty() ? "-" : k.unit),
                     markdown_cell(io::key_default_text(k)), markdown_cell(io::key_allowed_text(k)),
                     markdown_cell(k.description));
}

/// The parameters, then the keys that are not numbers of a model that has them.
std::string table(const std::vector<ParameterSpec>& parameters, const std::vector<io::KeySpec>& keys = {}) {
  std::string text = "| Parameter | Unit | Default | Allowed values | Description |\n|---|---|---|---|---|\n";
  for (const auto& k : keys) text += "| " + row(k);
  for (const auto& p : parameters) text += "| " + row(p);
  return text;
}

/// "a, b" -> {"a", "b"}.
std::vector<std::string> split_names(const std::string& list) {
  std::vector<std::string> names;
  std::istringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    if (!name.empty()) names.push_back(name);
  }
  return names;
}

bool declared_alike(const MaterialModel& model, const ParameterSpec& p) {
  return std::find(model.parameters.begin(), model.parameters.end(), p) != model.parameters.end();
}

/// The parameters of models[0] that every other listed model declares alike.
std::vector<ParameterSpec> shared(const std::vector<const MaterialModel*>& models) {
  std::vector<ParameterSpec> parameters;
  for (const auto& p : models[0]->parameters)
    if (std::all_of(models.begin(), models.end(), [&](const MaterialModel* m) { return declared_alike(*m, p); }))
      parameters.push_back(p);
  return parameters;
}

std::string specific_table(const std::vector<const MaterialModel*>& models) {
  const auto common = shared(models);
  std::string text =
      "| Model | Parameter | Unit | Default | Allowed values | Description |\n|---|---|---|---|---|---|\n";
  for (const MaterialModel* model : models)
    for (const auto& p : model->parameters)
      if (std::find(common.begin(), common.end(), p) == common.end())
        text += fmt::format("| `{}` | ", model->key) + row(p);
  return text;
}

}  // namespace

std::string material_reference_block(const std::string& content, bool* all_models_known) {
  if (all_models_known) *all_models_known = true;
  if (content == "parameters added to every model") return table(common_material_parameters());
  const std::string of = "parameters of ", specific = "parameters specific to ";
  const bool is_of = content.rfind(of, 0) == 0, is_specific = content.rfind(specific, 0) == 0;
  if (!is_of && !is_specific)
    throw std::invalid_argument("unknown generated block '" + content + "'; expected '" + of + "A, B', '" + specific +
                                "A, B' or 'parameters added to every model'");
  const auto names = split_names(content.substr((is_of ? of : specific).size()));
  if (names.empty()) throw std::invalid_argument("generated block '" + content + "' names no model");
  std::vector<const MaterialModel*> models;
  for (const auto& name : names) {
    const MaterialModel* model = find_material_model(name);
    if (!model) {
      if (all_models_known) *all_models_known = false;
      return {};
    }
    models.push_back(model);
  }
  if (is_of && models.size() == 1) return table(models[0]->parameters, models[0]->keys);
  return is_of ? table(shared(models)) : specific_table(models);
}

std::string material_reference() {
  std::string text;
  for (const auto& name : material_model_names()) {
    const MaterialModel& model = *find_material_model(name);
    text += fmt::format("### {}\n\n{}\n\n{}\n", model.key, model.description, table(model.parameters, model.keys));
  }
  if (!common_material_parameters().empty())
    text += "### parameters added to every model\n\n" + table(common_material_parameters());
  return text;
}

}  // namespace mpm
