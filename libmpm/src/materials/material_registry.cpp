#include "mpm/materials/material_registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "elastic_models.hpp"
#include "mpm/core/kind_table.hpp"

namespace mpm {
namespace {

/// The registered models, the core's first (core/kind_table.hpp); listed by key.
KindTable<MaterialModel, &MaterialModel::key>& registry() {
  static KindTable<MaterialModel, &MaterialModel::key> table{[] {
    std::deque<MaterialModel> core;
    for (auto& model : elastic_material_models()) core.push_back(std::move(model));
    return core;
  }()};
  return table;
}

/// Parameters that an optional module adds to every model (the thermal module: conductivity, expansion).
std::vector<ParameterSpec>& common_parameters() {
  static std::vector<ParameterSpec> specs;
  return specs;
}

bool declares(const std::vector<ParameterSpec>& specs, const std::string& name) {
  return std::any_of(specs.begin(), specs.end(), [&](const ParameterSpec& p) { return p.name == name; });
}

}  // namespace

ParameterSpec ParameterSpec::required(std::string name, std::string unit, io::Range range, std::string description) {
  return {std::move(name), std::move(unit), range, std::nullopt, "", std::move(description), "", {}};
}

ParameterSpec ParameterSpec::with_default(std::string name, std::string unit, double value, io::Range range,
                                          std::string description) {
  return {std::move(name), std::move(unit), range, value, "", std::move(description), "", {}};
}

ParameterSpec ParameterSpec::optional(std::string name, std::string unit, io::Range range, std::string absent,
                                      std::string description) {
  return {std::move(name), std::move(unit), range, std::nullopt, std::move(absent), std::move(description), "", {}};
}

ParameterSpec ParameterSpec::choice(std::string name, std::vector<std::string> choices, int default_index,
                                    std::string description) {
  const auto last = static_cast<double>(choices.size()) - 1;
  ParameterSpec spec{
      std::move(name), "-", io::Range::closed(0, last), default_index, "", std::move(description), "", {}};
  spec.choices = std::move(choices);
  return spec;
}

ParameterSpec ParameterSpec::only_with(std::string parameter) const {
  ParameterSpec spec = *this;
  spec.applies_with = std::move(parameter);
  return spec;
}

void register_material_model(MaterialModel model) { registry().add(std::move(model)); }

const MaterialModel* find_material_model(std::string_view key) { return registry().find(key); }

std::vector<std::string> material_model_names() {
  std::vector<std::string> names = registry().names();
  std::sort(names.begin(), names.end());
  return names;
}

std::string material_model_names_where(const std::function<bool(const MaterialModel&)>& accept) {
  std::vector<std::string> names;
  for (const auto& key : material_model_names())
    if (accept(*find_material_model(key))) names.push_back(key);
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return text;
}

void register_common_material_parameters(const std::vector<ParameterSpec>& specs) {
  for (const auto& spec : specs)
    if (!declares(common_parameters(), spec.name)) common_parameters().push_back(spec);
}

const std::vector<ParameterSpec>& common_material_parameters() { return common_parameters(); }

std::vector<ParameterSpec> material_parameters(const MaterialModel& model) {
  std::vector<ParameterSpec> parameters = model.parameters;
  for (const auto& common : common_parameters())
    if (!declares(model.parameters, common.name)) parameters.push_back(common);
  return parameters;
}

double material_parameter(const MaterialDescription& description, std::string_view name) {
  if (const auto it = description.parameters.find(std::string(name)); it != description.parameters.end())
    return it->second;
  if (const MaterialModel* model = find_material_model(description.model))
    for (const auto& p : material_parameters(*model))
      if (p.name == name && p.default_value) return *p.default_value;
  throw std::out_of_range("material '" + description.name + "' has no parameter '" + std::string(name) + "'");
}

template <int Dim>
std::unique_ptr<Material<Dim>> make_material(const MaterialDescription& description) {
  const MaterialModel* model = find_material_model(description.model);
  if (!model) throw std::invalid_argument("unknown material model '" + description.model + "'");
  if constexpr (Dim == 1) return model->make_1d(description);
  if constexpr (Dim == 2) return model->make_2d(description);
  if constexpr (Dim == 3) return model->make_3d(description);
}

template std::unique_ptr<Material<1>> make_material<1>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_material<2>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_material<3>(const MaterialDescription&);

}  // namespace mpm
