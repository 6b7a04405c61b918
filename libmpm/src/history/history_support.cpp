#include "history_support.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace mpm::history {

int read_body(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  std::vector<std::string> names;
  for (const auto& b : scene.bodies) names.push_back(b.name);
  const std::string name = reader.choice(value, names);
  return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
}

int read_set(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  std::vector<std::string> names;
  names.reserve(scene.sets.size());
  for (const auto& s : scene.sets) names.push_back(s.name);
  if (names.empty()) reader.fail(value, "the scene has no `sets:` section to name a set from");
  const std::string name = reader.choice(value, names);
  return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
}

std::vector<std::string> read_point_fields(const YamlReader& reader, const YamlValue& value) {
  std::vector<std::string> valid;
  for (auto& name : output_field_names())
    if (find_output_field(name)->components > 0) valid.push_back(std::move(name));
  std::vector<std::string> fields;
  for (const auto& item : reader.list(value, std::nullopt, "field names")) {
    std::string field = reader.choice(item, valid);
    if (std::find(fields.begin(), fields.end(), field) != fields.end())
      reader.fail(item, fmt::format("field '{}' is listed twice", field));
    fields.push_back(std::move(field));
  }
  return fields;
}

int read_axis(const YamlReader& reader, const YamlValue& value, int dimension) {
  std::vector<std::string> names{"x", "y", "z"};
  names.resize(static_cast<std::size_t>(dimension));
  const std::string axis = reader.choice(value, names);
  return static_cast<int>(std::find(names.begin(), names.end(), axis) - names.begin());
}

std::array<double, 3> read_point_in_grid(const YamlReader& reader, const YamlValue& value,
                                         const SceneDescription& scene, const char* what) {
  const auto x = reader.vector(value, scene.dimension, io::Range::any(), "m");
  const auto& g = scene.grid;
  for (int d = 0; d < scene.dimension; ++d)
    if (x[d] < g.origin[d] || x[d] > g.origin[d] + g.extent[d]) {
      std::vector<std::string> box;
      box.reserve(static_cast<std::size_t>(scene.dimension));
      for (int a = 0; a < scene.dimension; ++a)
        box.push_back(fmt::format("[{:g}, {:g}]", g.origin[a], g.origin[a] + g.extent[a]));
      reader.fail(value, fmt::format("the {} ({:g}) is outside the grid {}", what,
                                     fmt::join(x.begin(), x.begin() + scene.dimension, ", "), fmt::join(box, " x ")));
    }
  return x;
}

Box read_box(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  const YamlMap map = reader.map(value);
  map.allow({"min", "max"});
  Box box;
  box.min = reader.vector(map.required("min"), scene.dimension, io::Range::any(), "m");
  const YamlValue max = map.required("max");
  box.max = reader.vector(max, scene.dimension, io::Range::any(), "m");
  const auto& g = scene.grid;
  for (int d = 0; d < scene.dimension; ++d) {
    if (!(box.min[d] < box.max[d]))
      reader.fail(max, fmt::format("max must be above min on every axis ({:g} <= {:g} on axis {})", box.max[d],
                                   box.min[d], "xyz"[d]));
    if (box.max[d] < g.origin[d] || box.min[d] > g.origin[d] + g.extent[d])
      reader.fail(value,
                  fmt::format("the box is outside the grid (axis {}: [{:g}, {:g}] against the grid's [{:g}, {:g}])",
                              "xyz"[d], box.min[d], box.max[d], g.origin[d], g.origin[d] + g.extent[d]));
  }
  return box;
}

std::vector<std::string> component_suffixes(const OutputField& field, int dim) {
  switch (field.components) {
    case 1:
      return {""};
    case 3: {
      std::vector<std::string> s{"_x", "_y", "_z"};
      s.resize(static_cast<std::size_t>(dim));
      return s;
    }
    case 6:
      return {"_xx", "_yy", "_zz", "_xy", "_yz", "_xz"};
    default:
      return {"_xx", "_xy", "_xz", "_yx", "_yy", "_yz", "_zx", "_zy", "_zz"};
  }
}

void fail(const HistoryDescription& history, const std::string& key, const std::string& message) {
  throw SceneError(history.where, key.empty() ? history.path : history.path + "." + key, message);
}

template <int Dim>
std::vector<int> bodies_defining(const HistoryDescription& history, const std::vector<const OutputField*>& fields,
                                 int body, const std::vector<Body<Dim>>& bodies) {
  std::vector<int> selected;
  std::string first_reason;
  for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
    if (body >= 0 && b != body) continue;
    std::optional<std::string> reason;
    for (const OutputField* f : fields)
      if (!reason) reason = output_field_undefined_on<Dim>(*f, bodies[b]);
    if (!reason) {
      selected.push_back(b);
    } else {
      if (body >= 0) fail(history, "fields", *reason);
      if (first_reason.empty()) first_reason = *reason;
    }
  }
  if (selected.empty()) fail(history, "fields", "no body defines every field: " + first_reason);
  return selected;
}

template std::vector<int> bodies_defining<1>(const HistoryDescription&, const std::vector<const OutputField*>&, int,
                                             const std::vector<Body<1>>&);
template std::vector<int> bodies_defining<2>(const HistoryDescription&, const std::vector<const OutputField*>&, int,
                                             const std::vector<Body<2>>&);
template std::vector<int> bodies_defining<3>(const HistoryDescription&, const std::vector<const OutputField*>&, int,
                                             const std::vector<Body<3>>&);

}  // namespace mpm::history
