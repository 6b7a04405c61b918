// `type: polygon` (2D; docs/scene-reference.md, bodies[].shape): corners from the scene or from a text file, checked
// to form a simple polygon of non-zero area. Its area is known exactly (the shoelace formula), and `volume` defaults
// to it; `domains: conforming` meshes it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kinds.hpp"
#include "mpm/body_shape/polygon_region.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::shapes {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace polygon {

using Point = std::array<double, 2>;

/// Twice the signed area of triangle abc.
double orient(const Point& a, const Point& b, const Point& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// True when the closed segments ab and cd share a point.
bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  const auto on = [](const Point& p, const Point& q, const Point& x) {  // x on segment pq, given collinear
    return std::min(p[0], q[0]) <= x[0] && x[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= x[1] &&
           x[1] <= std::max(p[1], q[1]);
  };
  return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) || (o4 == 0 && on(c, d, b));
}

/// Corners from a polygon file: one corner "x y" (or "x, y") per line, in m; blank lines and lines starting
/// with '#' are skipped.
void read_polygon_file(const io::YamlReader& reader, const io::YamlValue& value, const std::string& scene_file,
                       std::vector<Point>& vertices) {
  const std::string name = reader.name(value);
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(scene_file).parent_path() / path;
  std::ifstream in(path);
  if (!in)
    reader.fail(value, fmt::format("polygon file '{}' not found or not readable (looked for {})", name, path.string()));
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream words(line);
    std::string x_text, y_text, extra;
    if (!(words >> x_text) || x_text[0] == '#') continue;
    words >> y_text >> extra;
    const auto x = io::parse_number(x_text), y = io::parse_number(y_text);
    if (!x || !y || !extra.empty())
      reader.fail(value, fmt::format("polygon file '{}', line {}: expected two numbers \"x y\" (m), got \"{}\"", name,
                                     number, line));
    vertices.push_back({*x, *y});
  }
}

/// Fails unless the corners form a simple polygon (no two non-adjacent edges meet) of non-zero area.
void check_simple(const io::YamlReader& reader, const io::YamlValue& where, const std::vector<Point>& corners) {
  const std::size_t n = corners.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) continue;
      if (segments_meet(corners[i], corners[(i + 1) % n], corners[j], corners[(j + 1) % n]))
        reader.fail(where, fmt::format("the polygon crosses itself: edge {} (corners {} and {}) meets edge {} "
                                       "(corners {} and {})",
                                       i, i, (i + 1) % n, j, j, (j + 1) % n));
    }
  double area = 0, lo[2] = {corners[0][0], corners[0][1]}, hi[2] = {corners[0][0], corners[0][1]};
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    area += corners[j][0] * corners[i][1] - corners[i][0] * corners[j][1];
    for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], corners[i][d]), hi[d] = std::max(hi[d], corners[i][d]);
  }
  if (std::abs(area) <= 1e-12 * (hi[0] - lo[0]) * (hi[1] - lo[1]) || hi[0] == lo[0] || hi[1] == lo[1])
    reader.fail(where, "the polygon has zero area");
}

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k{
      {.name = "vertices",
       .type = KeyType::list,
       .unit = "m",
       .absent = "required unless `file`",
       .description = "the corners, either orientation, not crossing itself, non-zero area (a repeated closing "
                      "corner is dropped)",
       .type_text = "list of at least 3 `[x, y]`"},
      {.name = "file",
       .type = KeyType::name,
       .absent = "instead of `vertices`",
       .description = "a text file of corners, one `x y` (or `x, y`) per line in m, blank lines and lines starting "
                      "with `#` skipped, relative to the scene file's folder"},
  };
  return k;
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  map.allow(typed_keys(keys()));
  PolygonShape polygon;
  const auto vertices = map.find("vertices"), file = map.find("file");
  if (vertices && file) reader.fail(*file, "give the corners either as vertices or in a file, not both");
  if (!vertices && !file) map.required("vertices", "key", " (or file: a text file of corners)");
  const io::YamlValue list = vertices ? *vertices : *file;
  if (file) {
    read_polygon_file(reader, *file, context.scene_file, polygon.vertices);
  } else {
    for (const auto& item : reader.list(list, std::nullopt, "[x, y] corners")) {
      const auto xy = reader.vector(item, 2, io::Range::any(), "m");
      polygon.vertices.push_back({xy[0], xy[1]});
    }
  }
  auto& corners = polygon.vertices;
  if (corners.size() > 3 && corners.front() == corners.back()) corners.pop_back();  // a closing corner repeated
  if (corners.size() < 3) reader.fail(list, fmt::format("a polygon needs at least 3 corners, got {}", corners.size()));
  check_simple(reader, list, corners);
  return polygon;
}

std::optional<ShapeBoundingBox> bounds(const std::any& spec, int) {
  const auto& vertices = std::any_cast<const PolygonShape&>(spec).vertices;
  std::array<double, 3> lo{vertices[0][0], vertices[0][1], 0}, hi = lo;
  for (const auto& corner : vertices)
    for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], corner[d]), hi[d] = std::max(hi[d], corner[d]);
  return ShapeBoundingBox{lo, hi};
}

std::unique_ptr<Region<2>> region(const std::any& spec, std::vector<std::string>*) {
  PolygonRegion::Loop loop;
  for (const auto& v : std::any_cast<const PolygonShape&>(spec).vertices) loop.emplace_back(v[0], v[1]);
  return std::make_unique<PolygonRegion>(std::vector<PolygonRegion::Loop>{loop});
}

}  // namespace polygon
}  // namespace

ShapeKind polygon_kind() {
  using namespace polygon;
  ShapeKind k;
  k.name = "polygon";
  k.noun = "a polygon";
  k.description = "a simple polygon from its corners (in the scene or a text file)";
  k.keys = keys();
  k.traits.dimensions = {false, true, false};
  k.traits.exact_volume = true;
  k.traits.exact_by_default = true;
  k.traits.conforming_mesh = true;
  k.parse = parse;
  k.bounds = bounds;
  k.region_2d = region;
  return k;
}

}  // namespace mpm::shapes
