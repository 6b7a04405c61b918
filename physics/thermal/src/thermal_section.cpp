#include "thermal_section.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "mpm/expression.hpp"
#include "mpm/scene_error.hpp"
#include "mpm/thermal/thermal_description.hpp"

namespace mpm::thermal {
namespace {

constexpr const char* face_names[6] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};

/// Checked access to the section's values, errors at FILE:LINE:COLUMN and the dotted key.
struct SectionReader {
  std::string file;

  SourceLocation at(const YAML::Node& node, const YAML::Mark& fallback = YAML::Mark::null_mark()) const {
    const YAML::Mark m = node.IsDefined() && !node.IsNull() && !node.Mark().is_null() ? node.Mark() : fallback;
    if (m.is_null()) return {file, 0, 0};
    return {file, m.line + 1, m.column + 1};
  }
  [[noreturn]] void fail(const YAML::Node& node, const std::string& key, const std::string& message) const {
    throw SceneError(at(node), key, message);
  }
  /// A map whose keys are all in `allowed`.
  void map(const YAML::Node& node, const std::string& key, const std::vector<std::string>& allowed) const {
    if (!node.IsMap()) fail(node, key, "expected a map");
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string k = it->first.Scalar();
      bool ok = false;
      for (const auto& a : allowed) ok = ok || a == k;
      if (!ok) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        throw SceneError(at(it->first), key + "." + k, fmt::format("unknown key '{}'; valid keys: {}", k, list));
      }
    }
  }
  double number(const YAML::Node& node, const std::string& key) const {
    double v = 0;
    if (node.IsScalar()) {
      std::string_view t = node.Scalar();
      if (!t.empty() && t.front() == '+') t.remove_prefix(1);
      const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), v);
      if (error == std::errc() && end == t.data() + t.size() && std::isfinite(v)) return v;
    }
    fail(node, key, "expected a number");
  }
  /// A number or a muparser expression of `variables`, as text.
  std::string expression(const YAML::Node& node, const std::string& key, const std::vector<std::string>& variables,
                         const std::string& unit) const {
    if (!node.IsScalar() || node.Scalar().empty())
      fail(node, key, fmt::format("expected a number ({}) or an expression of {}", unit, fmt::join(variables, ", ")));
    try {
      const Expression e(node.Scalar(), variables);
      if (e.is_constant() && !std::isfinite(e.constant_value()))
        fail(node, key, fmt::format("\"{}\" is not finite", node.Scalar()));
    } catch (const std::invalid_argument& e) {
      fail(node, key, fmt::format("{} (variables allowed here: {})", e.what(), fmt::join(variables, ", ")));
    }
    return node.Scalar();
  }
  std::array<double, 3> vector(const YAML::Node& node, const std::string& key, int dimension) const {
    if (!node.IsSequence() || static_cast<int>(node.size()) != dimension)
      fail(node, key, fmt::format("expected a list of {} numbers (m)", dimension));
    std::array<double, 3> v{0, 0, 0};
    for (int d = 0; d < dimension; ++d) v[d] = number(node[d], fmt::format("{}[{}]", key, d));
    return v;
  }
};

}  // namespace

std::any parse_thermal_section(const YAML::Node& node, const SceneDescription& scene) {
  const SectionReader r{scene.file};
  const std::string key = section_key;
  const int dim = scene.dimension;
  ThermalDescription t;
  t.where = r.at(node);
  if (node.IsNull()) return t;  // `thermal:` alone: conduction with insulated boundaries
  r.map(node, key, {"initial_temperature", "source", "boundary", "fixed_temperature"});
  if (const auto v = node["initial_temperature"])
    t.initial_temperature = r.expression(v, key + ".initial_temperature", {"x", "y", "z"}, "K");
  if (const auto v = node["source"]) t.source = r.expression(v, key + ".source", {"x", "y", "z", "t"}, "W/m^3");
  if (const auto b = node["boundary"]) {
    const std::vector<std::string> faces(face_names, face_names + 2 * dim);
    r.map(b, key + ".boundary", faces);
    for (int f = 0; f < 2 * dim; ++f) {
      const auto face = b[face_names[f]];
      if (!face) continue;
      const std::string fkey = key + ".boundary." + face_names[f];
      r.map(face, fkey, {"temperature", "flux"});
      ThermalFace& tf = t.boundary[f];
      tf.where = r.at(face);
      if (face["temperature"] && face["flux"])
        r.fail(face["flux"], fkey + ".flux", "give either temperature (K) or flux (W/m^2) on a face, not both");
      if (const auto v = face["temperature"]) tf.temperature = r.expression(v, fkey + ".temperature", {"t"}, "K");
      if (const auto v = face["flux"]) tf.flux = r.expression(v, fkey + ".flux", {"t"}, "W/m^2");
      if (!tf.temperature && !tf.flux) r.fail(face, fkey, "expected temperature: ... (K) or flux: ... (W/m^2)");
    }
  }
  if (const auto list = node["fixed_temperature"]) {
    if (!list.IsSequence()) r.fail(list, key + ".fixed_temperature", "expected a list of {min, max, temperature}");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const auto item = list[i];
      const std::string ikey = fmt::format("{}.fixed_temperature[{}]", key, i);
      r.map(item, ikey, {"min", "max", "temperature"});
      FixedTemperatureRegion region;
      region.where = r.at(item);
      for (const char* k : {"min", "max", "temperature"})
        if (!item[k]) r.fail(item, ikey + "." + k, fmt::format("missing required key '{}'", k));
      region.min = r.vector(item["min"], ikey + ".min", dim);
      region.max = r.vector(item["max"], ikey + ".max", dim);
      for (int d = 0; d < dim; ++d)
        if (!(region.max[d] > region.min[d])) r.fail(item["max"], ikey + ".max", "must exceed min on every axis");
      region.temperature = r.expression(item["temperature"], ikey + ".temperature", {"t"}, "K");
      t.fixed_temperature.push_back(std::move(region));
    }
  }
  return t;
}

}  // namespace mpm::thermal
