#include "mpm/scene_loader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <tuple>
#include <utility>

#include "mpm/expression.hpp"
#include "mpm/material_catalog.hpp"
#include "mpm/output_writer.hpp"
#include "mpm/scene_extension.hpp"
#include "mpm/scheme.hpp"

namespace mpm {
namespace {

// ---------------------------------------------------------------------------------------------------
// Vocabulary of the format (docs/scene-reference.md).

constexpr const char* axis_names[3] = {"x", "y", "z"};
constexpr const char* face_names[6] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
/// Relative tolerance of "extent / cell_size is an integer" and of "the body lies inside the grid".
constexpr double geometric_tolerance = 1e-9;

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

bool contains(const std::vector<std::string>& items, const std::string& item) {
  return std::find(items.begin(), items.end(), item) != items.end();
}

/// " unit" for messages; nothing for dimensionless quantities ("-" or "").
std::string unit_suffix(std::string_view unit) {
  return unit.empty() || unit == "-" ? std::string() : " " + std::string(unit);
}

/// A finite number written as `text` (leading '+' allowed), or nothing.
std::optional<double> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// An admissible interval of a number, for checks and for "must be ..." messages.
struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  bool lower_inclusive = true;
  double upper = std::numeric_limits<double>::infinity();
  bool upper_inclusive = true;

  bool contains(double v) const {
    return (v > lower || (lower_inclusive && v == lower)) && (v < upper || (upper_inclusive && v == upper));
  }
  /// "> 0", ">= 0", "in (0, 1]", ...
  std::string describe(std::string_view unit) const {
    const bool has_lower = std::isfinite(lower), has_upper = std::isfinite(upper);
    if (has_lower && has_upper)
      return fmt::format("in {}{}, {}{}{}", lower_inclusive ? '[' : '(', lower, upper, upper_inclusive ? ']' : ')',
                         unit_suffix(unit));
    if (has_lower) return fmt::format("{} {}{}", lower_inclusive ? ">=" : ">", lower, unit_suffix(unit));
    if (has_upper) return fmt::format("{} {}{}", upper_inclusive ? "<=" : "<", upper, unit_suffix(unit));
    return "finite";
  }
};
const Range any_number{};
const Range positive{0.0, false};
const Range non_negative{0.0, true};
const Range zero_to_one{0.0, true, 1.0, true};
const Range above_zero_to_one{0.0, false, 1.0, true};

/// A YAML node together with its dotted key path and the place to report it at.
struct Value {
  YAML::Node node;
  std::string path;  ///< e.g. "bodies[1].shape.radius"
  YAML::Mark mark;   ///< of the node; of its key when the node is empty (yaml-cpp has no mark for it)
};

/// The mark to report `node` at. yaml-cpp places an empty value (`key:`) at the next token, which can be
/// lines away, so empty values are reported at `fallback` (their key).
YAML::Mark mark_of(const YAML::Node& node, const YAML::Mark& fallback) {
  return node.IsNull() || node.Mark().is_null() ? fallback : node.Mark();
}

/// What a node is, for "expected X, got Y" messages.
std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      return "'" + node.Scalar() + "'";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    default:
      return "nothing";
  }
}

class MapReader;

/// Typed access to scene values: each accessor checks the YAML type and the range and otherwise
/// throws a SceneError located at the value, naming its key path.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  SourceLocation location(const YAML::Mark& mark) const {
    if (mark.is_null()) return {file_, 0, 0};
    return {file_, mark.line + 1, mark.column + 1};
  }

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& key, const std::string& message) const {
    throw SceneError(location(mark), key, message);
  }
  [[noreturn]] void fail(const Value& value, const std::string& message) const {
    fail(value.mark, value.path, message);
  }

  /// A finite number.
  double number(const Value& v) const {
    if (v.node.IsScalar())
      if (const auto x = parse_number(v.node.Scalar())) return *x;
    fail(v, "expected a number, got " + describe(v.node));
  }
  /// A finite number in `range` (`unit` is only used in the message).
  double number(const Value& v, const Range& range, std::string_view unit) const {
    const double x = number(v);
    if (!range.contains(x))
      fail(v, fmt::format("out of range: must be {}, got {}{}", range.describe(unit), x, unit_suffix(unit)));
    return x;
  }
  /// An integer >= minimum.
  int integer(const Value& v, int minimum) const {
    std::optional<double> x;
    if (v.node.IsScalar()) x = parse_number(v.node.Scalar());
    if (!x || std::floor(*x) != *x) fail(v, "expected an integer, got " + describe(v.node));
    if (*x < minimum) fail(v, fmt::format("out of range: must be >= {}, got {}", minimum, *x));
    if (*x > std::numeric_limits<int>::max()) fail(v, fmt::format("too large: {}", *x));
    return static_cast<int>(*x);
  }
  /// A scalar, as text.
  std::string string(const Value& v) const {
    if (!v.node.IsScalar()) fail(v, "expected a string, got " + describe(v.node));
    return v.node.Scalar();
  }
  /// A non-empty scalar, as text.
  std::string name(const Value& v) const {
    std::string text = string(v);
    if (text.empty()) fail(v, "must not be empty");
    return text;
  }
  /// One of `allowed`.
  std::string choice(const Value& v, const std::vector<std::string>& allowed) const {
    const bool ok = v.node.IsScalar() && contains(allowed, v.node.Scalar());
    if (!ok) fail(v, fmt::format("invalid value {}; valid values: {}", describe(v.node), join(allowed)));
    return v.node.Scalar();
  }
  /// true/false (also yes/no, on/off as YAML allows).
  bool boolean(const Value& v) const {
    bool b = false;
    if (!v.node.IsScalar() || !YAML::convert<bool>::decode(v.node, b))
      fail(v, "expected true or false, got " + describe(v.node));
    return b;
  }
  /// The entries of a list; with `length`, exactly that many. `what` names the entries in messages.
  std::vector<Value> list(const Value& v, std::optional<std::size_t> length, std::string_view what) const {
    if (!v.node.IsSequence()) {
      if (length) fail(v, fmt::format("expected a list of {} {}, got {}", *length, what, describe(v.node)));
      fail(v, fmt::format("expected a list of {}, got {}", what, describe(v.node)));
    }
    if (length && v.node.size() != *length)
      fail(v, fmt::format("expected a list of {} {} (one per axis), got {} {}", *length, what, v.node.size(),
                          v.node.size() == 1 ? "entry" : "entries"));
    std::vector<Value> items;
    for (std::size_t i = 0; i < v.node.size(); ++i) {
      const YAML::Node item = v.node[i];
      items.push_back({item, fmt::format("{}[{}]", v.path, i), mark_of(item, v.mark)});
    }
    return items;
  }
  /// A number or a list of `dimension` numbers: the value for each axis.
  std::vector<Value> per_axis(const Value& v, int dimension, std::string_view what) const {
    if (v.node.IsScalar()) return std::vector<Value>(dimension, v);
    if (!v.node.IsSequence())
      fail(v, fmt::format("expected a number or a list of {} {}, got {}", dimension, what, describe(v.node)));
    return list(v, dimension, what);
  }
  /// A list of `dimension` numbers in `range`, padded with zeros to 3.
  std::array<double, 3> vector(const Value& v, int dimension, const Range& range, std::string_view unit) const {
    std::array<double, 3> result{0, 0, 0};
    const auto items = list(v, dimension, "numbers");
    for (int d = 0; d < dimension; ++d) result[d] = number(items[d], range, unit);
    return result;
  }
  /// A number or a muparser expression of `variables`, as expression text (numbers in shortest form).
  std::string expression(const Value& v, const std::vector<std::string>& variables) const {
    if (!v.node.IsScalar() || v.node.Scalar().empty())
      fail(v, fmt::format("expected a number or an expression of {}, got {}", join(variables), describe(v.node)));
    if (const auto x = parse_number(v.node.Scalar())) return fmt::format("{}", *x);
    try {
      const Expression e(v.node.Scalar(), variables);
      if (e.is_constant() && !std::isfinite(e.constant_value()))
        fail(v, fmt::format("expression \"{}\" evaluates to {}", v.node.Scalar(), e.constant_value()));
    } catch (const std::invalid_argument& e) {
      fail(v, fmt::format("{} (variables allowed here: {})", e.what(), join(variables)));
    }
    return v.node.Scalar();
  }

  /// Opens `v` as a map (defined below).
  MapReader map(const Value& v) const;

 private:
  std::string file_;
};

/// A YAML map being read: finds keys, rejects unknown and duplicate ones, reports missing ones.
class MapReader {
 public:
  struct Entry {
    std::string key;
    YAML::Mark key_mark;
    Value value;
  };

  /// Fails unless `v` is a map with plain, distinct keys.
  MapReader(const Reader& reader, Value v) : reader_(reader), self_(std::move(v)) {
    if (!self_.node.IsMap()) reader_.fail(self_, "expected a map, got " + describe(self_.node));
    for (auto it = self_.node.begin(); it != self_.node.end(); ++it) {
      const YAML::Node key = it->first;
      const YAML::Mark key_mark = mark_of(key, self_.mark);
      if (!key.IsScalar()) reader_.fail(key_mark, self_.path, "keys must be plain names, got " + describe(key));
      const std::string name = key.Scalar();
      const std::string path = path_of(name);
      if (const Entry* first = find_entry(name))
        reader_.fail(key_mark, path,
                     fmt::format("duplicate key (first given at line {})", reader_.location(first->key_mark).line));
      entries_.push_back({name, key_mark, {it->second, path, mark_of(it->second, key_mark)}});
    }
  }

  /// Fails on the first key not in `allowed`: "unknown <noun> 'k'<context>; valid <noun>s: ...".
  void allow(const std::vector<std::string>& allowed, std::string_view noun = "key",
             std::string_view context = "") const {
    for (const auto& e : entries_)
      if (!contains(allowed, e.key))
        reader_.fail(e.key_mark, e.value.path,
                     fmt::format("unknown {} '{}'{}; valid {}s: {}", noun, e.key, context, noun, join(allowed)));
  }

  std::optional<Value> find(std::string_view key) const {
    if (const Entry* e = find_entry(key)) return e->value;
    return std::nullopt;
  }

  /// The value of `key`; if it is absent, fails at this map with "missing required <noun>...".
  Value required(std::string_view key, std::string_view noun = "key", std::string_view detail = "") const {
    if (const Entry* e = find_entry(key)) return e->value;
    reader_.fail(self_.mark, path_of(key), fmt::format("missing required {} '{}'{}", noun, key, detail));
  }

  const std::vector<Entry>& entries() const { return entries_; }
  const Value& self() const { return self_; }
  std::string path_of(std::string_view key) const {
    return self_.path.empty() ? std::string(key) : self_.path + "." + std::string(key);
  }

 private:
  const Entry* find_entry(std::string_view key) const {
    for (const auto& e : entries_)
      if (e.key == key) return &e;
    return nullptr;
  }

  const Reader& reader_;
  Value self_;
  std::vector<Entry> entries_;
};

MapReader Reader::map(const Value& v) const { return MapReader(*this, v); }

// ---------------------------------------------------------------------------------------------------
// Sections, in the order they are read.

int read_dimension(const Reader& r, const MapReader& top) {
  const Value v = top.required("dimension");
  const int dimension = r.integer(v, std::numeric_limits<int>::min());
  if (dimension < 1 || dimension > 3) r.fail(v, fmt::format("must be 1, 2 or 3, got {}", dimension));
  return dimension;
}

void read_boundary(const Reader& r, const Value& v, int dimension, GridDescription& grid) {
  const MapReader faces = r.map(v);
  const std::vector<std::string> valid(face_names, face_names + 2 * dimension);
  faces.allow(valid, "face", fmt::format(" in {}D", dimension));
  for (const auto& e : faces.entries()) {
    const int face = static_cast<int>(std::find(valid.begin(), valid.end(), e.key) - valid.begin());
    const int normal_axis = face / 2;
    FaceBoundary& boundary = grid.boundary[face];
    boundary.where = r.location(e.value.mark);
    if (e.value.node.IsMap()) {
      const MapReader condition = r.map(e.value);
      condition.allow({"velocity", "traction"});
      const auto velocity = condition.find("velocity");
      const auto traction = condition.find("traction");
      if (!velocity && !traction) r.fail(e.value, "expected velocity: [...] and/or traction: [...]");
      if (velocity) {
        const auto components = r.list(*velocity, dimension, "components");
        for (int d = 0; d < dimension; ++d) {
          if (components[d].node.IsScalar() && components[d].node.Scalar() == "free") continue;
          boundary.component[d] = r.expression(components[d], {"t"});
        }
      }
      if (traction) {
        const auto components = r.list(*traction, dimension, "components");
        for (int d = 0; d < dimension; ++d) {
          if (boundary.component[d])
            r.fail(components[d],
                   fmt::format("component {} of face {} has both a velocity and a traction", axis_names[d], e.key));
          boundary.traction[d] = r.expression(components[d], {"t"});
        }
      }
    } else if (e.value.node.IsScalar()) {
      const std::string kind = r.choice(e.value, {"fixed", "slip", "free"});
      if (kind == "fixed")
        for (int d = 0; d < dimension; ++d) boundary.component[d] = "0";
      else if (kind == "slip")
        boundary.component[normal_axis] = "0";
    } else {
      r.fail(e.value, "expected fixed, slip, free or {velocity: [...]}, got " + describe(e.value.node));
    }
  }
}

GridDescription read_grid(const Reader& r, const Value& v, int dimension) {
  const MapReader m = r.map(v);
  m.allow({"origin", "extent", "cell_size", "boundary"});
  GridDescription grid;
  if (const auto origin = m.find("origin")) grid.origin = r.vector(*origin, dimension, any_number, "m");
  grid.extent = r.vector(m.required("extent"), dimension, positive, "m");
  const Value cell_size = m.required("cell_size");
  const auto sizes = r.per_axis(cell_size, dimension, "numbers");
  for (int d = 0; d < dimension; ++d) {
    grid.cell_size[d] = r.number(sizes[d], positive, "m");
    const double ratio = grid.extent[d] / grid.cell_size[d];
    const double cells = std::round(ratio);
    if (cells < 1 || std::abs(ratio - cells) > geometric_tolerance * ratio)
      r.fail(sizes[d], fmt::format("extent {} m on axis {} is not a whole number of cells of {} m "
                                   "(extent / cell_size = {:.10g})",
                                   grid.extent[d], axis_names[d], grid.cell_size[d], ratio));
    if (cells > 1e9) r.fail(sizes[d], fmt::format("{} cells on axis {} is too many", cells, axis_names[d]));
    grid.cells[d] = static_cast<int>(cells);
  }
  if (const auto boundary = m.find("boundary")) read_boundary(r, *boundary, dimension, grid);
  return grid;
}

MaterialDescription read_material(const Reader& r, const MapReader::Entry& entry) {
  MaterialDescription material;
  material.name = entry.key;
  material.where = r.location(entry.key_mark);
  if (material.name.empty()) r.fail(entry.key_mark, entry.value.path, "material name must not be empty");
  const MapReader m = r.map(entry.value);
  const Value model = m.required("model");
  material.model = r.string(model);
  const MaterialModelSpec* spec = find_material_model(material.model);
  if (!spec)
    r.fail(model,
           fmt::format("unknown material model '{}'; valid models: {}", material.model, join(material_model_names())));
  std::vector<std::string> keys{"model"};
  for (const auto& p : spec->parameters) keys.push_back(p.name);
  m.allow(keys, "parameter", " for model " + material.model);
  for (const auto& p : spec->parameters) {
    if (const auto value = m.find(p.name)) {
      const Range range{p.lower, p.lower_inclusive, p.upper, p.upper_inclusive};
      material.parameters[p.name] = r.number(*value, range, p.unit);
    } else if (p.default_value) {
      material.parameters[p.name] = *p.default_value;
    } else if (!p.optional) {
      m.required(p.name, "parameter",
                 fmt::format(" of model {} ({}{})", material.model, p.description,
                             p.unit.empty() || p.unit == "-" ? "" : ", " + p.unit));
    }
  }
  if (spec->check)
    if (const auto error = spec->check(material.parameters)) {
      if (const auto value = m.find(error->key)) r.fail(*value, error->message);
      r.fail(entry.key_mark, m.path_of(error->key), error->message);
    }
  return material;
}

std::map<std::string, MaterialDescription> read_materials(const Reader& r, const Value& v) {
  const MapReader m = r.map(v);
  if (m.entries().empty()) r.fail(v, "at least one material is required");
  std::map<std::string, MaterialDescription> materials;
  for (const auto& entry : m.entries()) materials[entry.key] = read_material(r, entry);
  return materials;
}

/// Shape types per dimension (index 1..3), given with `type:`.
const std::vector<std::string> shape_types[4] = {
    {}, {"box"}, {"box", "disk", "polygon"}, {"box", "sphere", "cylinder"}};
/// Shapes given by their own key instead of `type:` (a file or a list of shapes).
const std::vector<std::string> shape_kinds = {"mesh", "image", "union", "intersection", "difference"};

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

/// A mesh or image file name: relative names are taken from the scene file's folder; the format (by
/// extension) must be one of `extensions` and the file must exist.
std::string read_file_name(const Reader& r, const Value& v, const std::string& scene_file,
                           const std::vector<std::string>& extensions, std::string_view what) {
  const std::string name = r.name(v);
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(scene_file).parent_path() / path;
  const std::string ext = lower_case(path.extension().string());
  if (!contains(extensions, ext))
    r.fail(v, fmt::format("unsupported {} format '{}' of '{}'; supported: {}", what, ext, name, join(extensions)));
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    r.fail(v, fmt::format("{} file '{}' not found (looked for {})", what, name, path.string()));
  return path.lexically_normal().string();
}

/// Twice the signed area of triangle abc.
double orient(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// True when the closed segments ab and cd share a point.
bool segments_meet(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c,
                   const std::array<double, 2>& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  const auto on = [](const auto& p, const auto& q, const auto& x) {  // x on segment pq, given collinear
    return std::min(p[0], q[0]) <= x[0] && x[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= x[1] &&
           x[1] <= std::max(p[1], q[1]);
  };
  return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) || (o4 == 0 && on(c, d, b));
}

/// Corners from a polygon file: one corner "x y" (or "x, y") per line, in m; blank lines and lines starting
/// with '#' are skipped.
void read_polygon_file(const Reader& r, const Value& v, const std::string& scene_file, ShapeDescription& shape) {
  const std::string name = r.name(v);
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(scene_file).parent_path() / path;
  std::ifstream in(path);
  if (!in) r.fail(v, fmt::format("polygon file '{}' not found or not readable (looked for {})", name, path.string()));
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream words(line);
    std::string x_text, y_text, extra;
    if (!(words >> x_text) || x_text[0] == '#') continue;
    words >> y_text >> extra;
    const auto x = parse_number(x_text), y = parse_number(y_text);
    if (!x || !y || !extra.empty())
      r.fail(v, fmt::format("polygon file '{}', line {}: expected two numbers \"x y\" (m), got \"{}\"", name, number,
                            line));
    shape.vertices.push_back({*x, *y});
  }
}

void read_polygon(const Reader& r, const MapReader& m, const std::string& scene_file, ShapeDescription& shape) {
  m.allow({"type", "vertices", "file"});
  const auto vertices = m.find("vertices"), file = m.find("file");
  if (vertices && file) r.fail(*file, "give the corners either as vertices or in a file, not both");
  if (!vertices && !file) m.required("vertices", "key", " (or file: a text file of corners)");
  const Value list = vertices ? *vertices : *file;
  if (file) {
    read_polygon_file(r, *file, scene_file, shape);
  } else {
    for (const auto& item : r.list(list, std::nullopt, "[x, y] corners")) {
      const auto xy = r.vector(item, 2, any_number, "m");
      shape.vertices.push_back({xy[0], xy[1]});
    }
  }
  auto& p = shape.vertices;
  if (p.size() > 3 && p.front() == p.back()) p.pop_back();  // a closing corner repeated
  if (p.size() < 3) r.fail(list, fmt::format("a polygon needs at least 3 corners, got {}", p.size()));
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) continue;
      if (segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]))
        r.fail(list, fmt::format("the polygon crosses itself: edge {} (corners {} and {}) meets edge {} (corners {} "
                                 "and {})",
                                 i, i, (i + 1) % n, j, j, (j + 1) % n));
    }
  double area = 0, lo[2] = {p[0][0], p[0][1]}, hi[2] = {p[0][0], p[0][1]};
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    area += p[j][0] * p[i][1] - p[i][0] * p[j][1];
    for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], p[i][d]), hi[d] = std::max(hi[d], p[i][d]);
  }
  if (std::abs(area) <= 1e-12 * (hi[0] - lo[0]) * (hi[1] - lo[1]) || hi[0] == lo[0] || hi[1] == lo[1])
    r.fail(list, "the polygon has zero area");
}

void read_mesh(const Reader& r, const MapReader& m, int dimension, const std::string& scene_file,
               ShapeDescription& shape) {
  const Value file = *m.find("mesh");
  if (dimension == 1) r.fail(file, "mesh bodies are available in 2D (a section of the mesh) and 3D");
  std::vector<std::string> keys{"mesh", "scale", "rotation", "translation"};
  if (dimension == 2) keys.push_back("section");
  m.allow(keys);
  shape.type = "mesh";
  shape.file = read_file_name(r, file, scene_file, {".stl", ".obj", ".off", ".ply"}, "mesh");
  if (const auto scale = m.find("scale")) shape.scale = r.number(*scale, positive, "");
  if (const auto rotation = m.find("rotation")) shape.rotation = r.vector(*rotation, 3, any_number, "degrees");
  if (const auto translation = m.find("translation")) shape.translation = r.vector(*translation, 3, any_number, "m");
  if (dimension == 2)
    shape.section =
        r.number(m.required("section", "key", " (a 2D body is the section of the mesh by the plane z = section, m)"));
}

void read_image(const Reader& r, const MapReader& m, int dimension, const std::string& scene_file, bool whole_shape,
                ShapeDescription& shape, std::vector<double>* labels) {
  const Value file = *m.find("image");
  if (dimension == 1) r.fail(file, "image bodies are available in 2D (.png, .pgm) and 3D (.vti)");
  m.allow({"image", "pixel_size", "origin", "threshold", "label", "labels", "resolution"});
  shape.type = "image";
  const std::vector<std::string> formats =
      dimension == 2 ? std::vector<std::string>{".png", ".pgm"} : std::vector<std::string>{".vti"};
  shape.file = read_file_name(r, file, scene_file, formats, fmt::format("{}D image", dimension));
  if (const auto size = m.find("pixel_size")) {
    const auto sizes = r.per_axis(*size, dimension, "numbers");
    for (int d = 0; d < dimension; ++d) shape.pixel_size[d] = r.number(sizes[d], positive, "m");
  } else if (dimension == 2) {
    m.required("pixel_size", "key", " (the size of a pixel, m)");
  }
  if (const auto origin = m.find("origin")) shape.image_origin = r.vector(*origin, dimension, any_number, "m");
  std::vector<Value> selections;
  for (const char* key : {"threshold", "label", "labels"})
    if (const auto value = m.find(key)) selections.push_back(*value);
  if (selections.empty())
    r.fail(m.self(),
           "an image body needs threshold (pixels with a value >= threshold), label (pixels with that value) "
           "or labels (one body per value)");
  if (selections.size() > 1) r.fail(selections[1], "give one of threshold, label and labels");
  if (const auto threshold = m.find("threshold")) shape.threshold = r.number(*threshold);
  if (const auto label = m.find("label")) shape.label = r.number(*label);
  if (const auto list = m.find("labels")) {
    if (!labels || !whole_shape)
      r.fail(*list, "labels (one body per label) needs the image to be the whole shape of the body; use label here");
    const auto items = r.list(*list, std::nullopt, "label values");
    if (items.empty()) r.fail(*list, "expected at least one label value");
    for (const auto& item : items) {
      const double value = r.number(item);
      if (std::find(labels->begin(), labels->end(), value) != labels->end())
        r.fail(item, fmt::format("label {} is listed twice", value));
      labels->push_back(value);
    }
  }
  if (const auto resolution = m.find("resolution")) {
    shape.pixel_particles = r.choice(*resolution, {"grid", "pixel"}) == "pixel";
    if (shape.pixel_particles && !whole_shape)
      r.fail(*resolution, "resolution: pixel needs the image to be the whole shape of the body");
  }
}

/// `labels` (may be null) receives the values of an image's `labels:` list (one body per label).
ShapeDescription read_shape(const Reader& r, const Value& v, int dimension, const std::string& scene_file,
                            bool whole_shape, std::vector<double>* labels) {
  const MapReader m = r.map(v);
  ShapeDescription shape;
  shape.where = r.location(v.mark);
  std::vector<std::string> given;
  for (const auto& key : std::vector<std::string>{"type", "mesh", "image", "union", "intersection", "difference"})
    if (m.find(key)) given.push_back(key);
  if (given.empty()) m.required("type", "key", " (or one of mesh, image, union, intersection, difference)");
  if (given.size() > 1)
    r.fail(*m.find(given[1]), fmt::format("a shape is either a type, a mesh, an image, a union, an intersection or a "
                                          "difference; this one has both {} and {}",
                                          given[0], given[1]));
  const std::string& kind = given[0];
  if (kind == "mesh") {
    read_mesh(r, m, dimension, scene_file, shape);
    return shape;
  }
  if (kind == "image") {
    read_image(r, m, dimension, scene_file, whole_shape, shape, labels);
    return shape;
  }
  if (kind != "type") {  // union, intersection, difference
    m.allow({kind});
    shape.type = kind;
    const Value list = *m.find(kind);
    const auto items = r.list(list, std::nullopt, "shapes");
    if (items.size() < 2) r.fail(list, fmt::format("a {} needs a list of at least 2 shapes", kind));
    for (const auto& item : items) shape.parts.push_back(read_shape(r, item, dimension, scene_file, false, nullptr));
    return shape;
  }
  const Value type = *m.find("type");
  shape.type = r.string(type);
  const auto& valid = shape_types[dimension];
  if (!contains(valid, shape.type)) {
    const bool elsewhere =
        shape.type == "disk" || shape.type == "sphere" || shape.type == "cylinder" || shape.type == "polygon";
    r.fail(type,
           fmt::format("{} '{}'{}; valid types in {}D: {} (or mesh, image, union, intersection, difference)",
                       elsewhere ? "shape type" : "unknown shape type", shape.type,
                       elsewhere ? fmt::format(" is not available in {}D", dimension) : "", dimension, join(valid)));
  }
  if (shape.type == "box") {
    m.allow({"type", "min", "max"});
    shape.min = r.vector(m.required("min"), dimension, any_number, "m");
    const Value max = m.required("max");
    shape.max = r.vector(max, dimension, any_number, "m");
    for (int d = 0; d < dimension; ++d)
      if (!(shape.min[d] < shape.max[d]))
        r.fail(max, fmt::format("max must exceed min on every axis; on axis {}: min {} m, max {} m", axis_names[d],
                                shape.min[d], shape.max[d]));
  } else if (shape.type == "polygon") {
    read_polygon(r, m, scene_file, shape);
  } else if (shape.type == "cylinder") {
    m.allow({"type", "center", "radius", "axis", "length"});
    shape.center = r.vector(m.required("center"), dimension, any_number, "m");
    shape.radius = r.number(m.required("radius"), positive, "m");
    if (const auto axis = m.find("axis")) {
      if (axis->node.IsSequence()) {  // any direction
        shape.direction = r.vector(*axis, 3, any_number, "");
        const double norm = std::hypot(shape.direction[0], shape.direction[1], shape.direction[2]);
        if (norm == 0) r.fail(*axis, "the axis direction must not be the zero vector");
        for (auto& c : shape.direction) c /= norm;
        shape.axis = -1;
        for (int d = 0; d < 3; ++d)
          if (std::abs(shape.direction[d]) == 1 && shape.direction[d] > 0) shape.axis = d;
      } else {
        if (!axis->node.IsScalar() || !contains({"x", "y", "z"}, axis->node.Scalar()))
          r.fail(*axis, fmt::format("invalid value {}; valid values: x, y, z or a direction [ax, ay, az]",
                                    describe(axis->node)));
        shape.axis = axis->node.Scalar()[0] - 'x';
      }
    }
    if (shape.axis >= 0) {
      shape.direction = {0, 0, 0};
      shape.direction[shape.axis] = 1;
    }
    shape.length = r.number(m.required("length"), positive, "m");
  } else {  // disk, sphere
    m.allow({"type", "center", "radius"});
    shape.center = r.vector(m.required("center"), dimension, any_number, "m");
    shape.radius = r.number(m.required("radius"), positive, "m");
  }
  return shape;
}

using Bounds = std::pair<std::array<double, 3>, std::array<double, 3>>;

/// Axis-aligned bounding box of a shape (first `dimension` axes meaningful), or nothing when only the
/// mesh or image file knows it (the scene builder checks those).
std::optional<Bounds> bounding_box(const ShapeDescription& s, int dimension) {
  if (s.type == "box") return Bounds{s.min, s.max};
  if (s.type == "mesh" || s.type == "image") return std::nullopt;
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
  if (s.type == "union" || s.type == "intersection" || s.type == "difference") {
    for (std::size_t k = 0; k < s.parts.size(); ++k) {
      const auto part = bounding_box(s.parts[k], dimension);
      if (!part) return std::nullopt;
      if (k == 0) {
        std::tie(lo, hi) = *part;
        if (s.type == "difference") break;
        continue;
      }
      for (int d = 0; d < dimension; ++d) {
        lo[d] = s.type == "union" ? std::min(lo[d], part->first[d]) : std::max(lo[d], part->first[d]);
        hi[d] = s.type == "union" ? std::max(hi[d], part->second[d]) : std::min(hi[d], part->second[d]);
      }
    }
    return Bounds{lo, hi};
  }
  if (s.type == "polygon") {
    lo = {s.vertices[0][0], s.vertices[0][1], 0};
    hi = lo;
    for (const auto& v : s.vertices)
      for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], v[d]), hi[d] = std::max(hi[d], v[d]);
    return Bounds{lo, hi};
  }
  for (int d = 0; d < dimension; ++d) {
    lo[d] = s.center[d] - s.radius;
    hi[d] = s.center[d] + s.radius;
    if (s.type == "cylinder") {  // center is the base centre; the end disks reach r sqrt(1 - a_d^2)
      const double a = s.direction[d], reach = s.radius * std::sqrt(std::max(0.0, 1 - a * a));
      lo[d] = std::min(s.center[d], s.center[d] + s.length * a) - reach;
      hi[d] = std::max(s.center[d], s.center[d] + s.length * a) + reach;
    }
  }
  return Bounds{lo, hi};
}

/// `labels` receives the values of an image shape's `labels:` list (the body is then one body per label).
BodyDescription read_body(const Reader& r, const Value& v, std::size_t index, const SceneDescription& scene,
                          std::vector<double>& labels) {
  const int dimension = scene.dimension;
  const MapReader m = r.map(v);
  m.allow({"name", "material", "shape", "particles_per_cell", "velocity", "domains"});
  BodyDescription body;
  body.where = r.location(v.mark);
  body.name = fmt::format("body{}", index);
  if (const auto name = m.find("name")) body.name = r.name(*name);

  const Value material = m.required("material");
  body.material = r.string(material);
  if (!scene.materials.count(body.material)) {
    std::vector<std::string> defined;
    for (const auto& [name, _] : scene.materials) defined.push_back(name);
    r.fail(material, fmt::format("unknown material '{}'; defined materials: {}", body.material, join(defined)));
  }

  const Value shape = m.required("shape");
  body.shape = read_shape(r, shape, dimension, scene.file, true, &labels);
  const auto box = bounding_box(body.shape, dimension);
  const GridDescription& grid = scene.grid;
  for (int d = 0; box && d < dimension; ++d) {
    const auto& [lo, hi] = *box;
    const double grid_lo = grid.origin[d], grid_hi = grid.origin[d] + grid.extent[d];
    const double tolerance = geometric_tolerance * grid.extent[d];
    if (lo[d] < grid_lo - tolerance || hi[d] > grid_hi + tolerance)
      r.fail(shape, fmt::format("body '{}' lies outside the grid: on axis {} it spans [{:.6g}, {:.6g}] m, the "
                                "grid [{:.6g}, {:.6g}] m",
                                body.name, axis_names[d], lo[d], hi[d], grid_lo, grid_hi));
  }

  body.particles_per_cell = {1, 1, 1};
  if (const auto ppc = m.find("particles_per_cell")) {
    const auto counts = r.per_axis(*ppc, dimension, "integers");
    for (int d = 0; d < dimension; ++d) body.particles_per_cell[d] = r.integer(counts[d], 1);
  } else {
    for (int d = 0; d < dimension; ++d) body.particles_per_cell[d] = 2;
  }

  if (const auto velocity = m.find("velocity")) {
    const auto components = r.list(*velocity, dimension, "components");
    for (int d = 0; d < dimension; ++d) body.velocity[d] = r.expression(components[d], {"x", "y", "z"});
  }
  if (const auto domains = m.find("domains")) body.domains = r.choice(*domains, {"lattice", "conforming"});
  return body;
}

std::vector<BodyDescription> read_bodies(const Reader& r, const Value& v, const SceneDescription& scene) {
  const auto items = r.list(v, std::nullopt, "bodies");
  if (items.empty()) r.fail(v, "at least one body is required");
  std::vector<BodyDescription> bodies;
  std::map<std::string, int> first_line;  // body name -> line of its definition
  for (std::size_t i = 0; i < items.size(); ++i) {
    std::vector<double> labels;
    const BodyDescription read = read_body(r, items[i], i, scene, labels);
    std::vector<BodyDescription> expanded{read};
    if (!labels.empty()) {  // an image with `labels:`: one body per label, named <name>_<label>
      expanded.clear();
      for (const double label : labels) {
        BodyDescription body = read;
        body.name = fmt::format("{}_{}", read.name, label);
        body.shape.label = label;
        expanded.push_back(std::move(body));
      }
    }
    for (auto& body : expanded) {
      if (const auto it = first_line.find(body.name); it != first_line.end()) {
        const auto name = r.map(items[i]).find("name");
        r.fail(name ? *name : items[i],
               fmt::format("duplicate body name '{}' (first used at line {})", body.name, it->second));
      }
      first_line[body.name] = body.where.line;
      bodies.push_back(std::move(body));
    }
  }
  return bodies;
}

// CPDI domain update (review §3.6): with F by default for cpdi_l2/cpdi_r4 and with the TLMPM (whose weights
// never change), with the tracked corners (CPDI2) for cpdi_q4, cpdi_t3 and cpdi_tet4.
void read_cpdi_domain_update(const Reader& r, const MapReader& m, SolverDescription& solver) {
  const ShapeFunctionInfo& info = *find_shape_function(solver.shape_function);
  const auto key = m.find("cpdi_domain_update");
  if (info.domain_corners == 0) {
    if (key) r.fail(*key, "cpdi_domain_update applies to the CPDI shape functions only, not " + solver.shape_function);
    return;
  }
  solver.cpdi_domain_update = info.domain_follows_F || solver.scheme == "tlmpm" ? "deformation_gradient" : "corners";
  if (!key) return;
  solver.cpdi_domain_update = r.choice(*key, {"deformation_gradient", "corners"});
  if (solver.cpdi_domain_update != "corners") return;
  if (solver.scheme == "tlmpm")
    r.fail(*key, "corners: the TLMPM keeps its reference weights, so its domains follow F; use deformation_gradient");
  if (solver.shape_function == "cpdi_r4")
    r.fail(*key, "cpdi_r4 is the parallelogram domain convected with F (eq. 3.27); use cpdi_q4 to track the corners");
}

SolverDescription read_solver(const Reader& r, const Value& v, const SceneDescription& scene) {
  const int dimension = scene.dimension;
  const MapReader m = r.map(v);
  m.allow({"scheme", "shape_function", "velocity_transfer", "flip_fraction", "dt", "cfl", "end_time", "mass_cutoff",
           "gravity", "snapshot_interval", "sort_interval", "cpdi_domain_update"});
  SolverDescription solver;
  if (const auto scheme = m.find("scheme")) solver.scheme = r.choice(*scheme, scheme_names());
  if (const auto shape_function = m.find("shape_function")) {
    solver.shape_function = r.choice(*shape_function, shape_function_names());
    const ShapeFunctionInfo& info = *find_shape_function(solver.shape_function);
    if (info.dimension != 0 && info.dimension != dimension)
      r.fail(*shape_function,
             fmt::format("{} is a {}D shape function; this scene is {}D (CPDI elements: cpdi_l2 in 1D, "
                         "cpdi_r4, cpdi_q4 and cpdi_t3 in 2D, cpdi_tet4 in 3D)",
                         info.name, info.dimension, dimension));
    if (info.tlmpm_only && solver.scheme != "tlmpm")
      r.fail(*shape_function, fmt::format("{} has negative weights and is only valid with scheme: tlmpm (particles at "
                                          "fixed reference positions); the scheme is {}",
                                          info.name, solver.scheme));
    for (int d = 0; d < dimension; ++d) {
      if (scene.grid.cells[d] < info.min_cells)
        r.fail(*shape_function, fmt::format("{} needs at least {} cells per axis; the grid has {} on axis {}",
                                            info.name, info.min_cells, scene.grid.cells[d], axis_names[d]));
      if (info.even_cells && scene.grid.cells[d] % 2 != 0)
        r.fail(*shape_function, fmt::format("{} needs an even number of cells per axis (two per element); the "
                                            "grid has {} on axis {}",
                                            info.name, scene.grid.cells[d], axis_names[d]));
    }
  }
  read_cpdi_domain_update(r, m, solver);
  if (const auto flip = m.find("flip_fraction")) solver.flip_fraction = r.number(*flip, zero_to_one, "");
  if (const auto transfer = m.find("velocity_transfer")) {
    solver.velocity_transfer = r.choice(*transfer, {"flip", "apic"});
    if (solver.velocity_transfer == "apic" && solver.scheme == "tlmpm")
      r.fail(*transfer, "apic is not available with tlmpm (review Remark 35: it does not work well with the TLMPM)");
    if (solver.velocity_transfer == "apic" && m.find("flip_fraction"))
      r.fail(*m.find("flip_fraction"), "flip_fraction applies to velocity_transfer: flip, not to apic");
  }

  const auto dt = m.find("dt");
  const auto cfl = m.find("cfl");
  if (dt && cfl) r.fail(*cfl, "give either dt (fixed time step) or cfl (adaptive time step), not both");
  if (!dt && !cfl)
    r.fail(v.mark, m.path_of("dt"), "one of dt (fixed time step, s) or cfl (adaptive time step) is required");
  if (dt) {
    solver.dt = r.number(*dt, positive, "s");
    solver.dt_where = r.location(dt->mark);
  } else {
    solver.cfl = r.number(*cfl, above_zero_to_one, "");
    solver.dt_where = r.location(cfl->mark);
  }

  solver.end_time = r.number(m.required("end_time"), positive, "s");
  if (const auto cutoff = m.find("mass_cutoff")) solver.mass_cutoff = r.number(*cutoff, non_negative, "");
  if (const auto gravity = m.find("gravity")) solver.gravity = r.vector(*gravity, dimension, any_number, "m/s^2");
  if (const auto n = m.find("snapshot_interval")) solver.snapshot_interval = r.integer(*n, 1);
  if (const auto n = m.find("sort_interval")) solver.sort_interval = r.integer(*n, 1);
  return solver;
}

OutputDescription read_output(const Reader& r, const Value& v) {
  const MapReader m = r.map(v);
  m.allow({"directory", "prefix", "interval", "fields", "grid"});
  OutputDescription output;
  output.where = r.location(v.mark);
  if (const auto directory = m.find("directory")) output.directory = r.name(*directory);
  if (const auto prefix = m.find("prefix")) {
    output.prefix = r.name(*prefix);
    if (output.prefix.find_first_of("/\\") != std::string::npos)
      r.fail(*prefix, "must be a file name prefix, not a path (use directory for the folder)");
  }
  if (const auto interval = m.find("interval")) output.interval = r.number(*interval, non_negative, "s");
  if (const auto fields = m.find("fields")) {
    output.fields.clear();
    for (const auto& item : r.list(*fields, std::nullopt, "field names")) {
      std::string field = r.choice(item, output_field_names());
      if (contains(output.fields, field)) r.fail(item, fmt::format("field '{}' is listed twice", field));
      output.fields.push_back(std::move(field));
    }
  }
  if (const auto grid = m.find("grid")) output.grid = r.boolean(*grid);
  return output;
}

}  // namespace

SceneDescription parse_scene(const std::string& yaml_text, const std::string& file_name_for_messages) {
  const Reader r(file_name_for_messages);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    r.fail(e.mark, "", "YAML syntax error: " + e.msg);
  }
  const std::string top_keys = "dimension, grid, materials, bodies, solver, output";
  if (root.IsNull())
    throw SceneError({file_name_for_messages, 1, 1}, "",
                     "the scene is empty: expected a map with the keys " + top_keys);
  const Value top_value{root, "", mark_of(root, YAML::Mark::null_mark())};
  if (!root.IsMap())
    r.fail(top_value, fmt::format("expected a map with the keys {}, got {}", top_keys, describe(root)));
  const MapReader top = r.map(top_value);
  std::vector<std::string> top_allowed{"dimension", "grid", "materials", "bodies", "solver", "output"};
  for (const auto& key : scene_extension_keys()) top_allowed.push_back(key);
  top.allow(top_allowed);

  SceneDescription scene;
  scene.file = file_name_for_messages;
  scene.dimension = read_dimension(r, top);
  scene.grid = read_grid(r, top.required("grid"), scene.dimension);
  scene.materials = read_materials(r, top.required("materials"));
  scene.bodies = read_bodies(r, top.required("bodies"), scene);
  scene.solver = read_solver(r, top.required("solver"), scene);
  if (const auto output = top.find("output")) scene.output = read_output(r, *output);
  for (const auto& key : scene_extension_keys())  // module sections last: they may refer to bodies
    if (const auto section = top.find(key))
      scene.extensions[key] = find_scene_extension(key)->parse(section->node, scene);
  return scene;
}

SceneDescription load_scene(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code error;
  if (!std::filesystem::exists(file, error)) throw SceneError({name, 0, 0}, "", "scene file not found");
  if (std::filesystem::is_directory(file, error))
    throw SceneError({name, 0, 0}, "", "is a directory, not a scene file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError({name, 0, 0}, "", "cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError({name, 0, 0}, "", "cannot read the scene file");
  return parse_scene(text.str(), name);
}

}  // namespace mpm
