// The registry of body shape kinds (mpm/body_shape/shape_kind.hpp): the core's kinds, then whatever modules
// register; reading a shape through its kind, its bounds, its region and its particles.
#include "mpm/body_shape/shape_kind.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <deque>
#include <filesystem>
#include <system_error>

#include "kinds.hpp"
#include "mpm/core/kind_table.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm {
namespace {

/// The core's kinds, then the modules' (core/kind_table.hpp).
KindTable<ShapeKind>& shape_table() {
  static KindTable<ShapeKind> t{shapes::core_shape_kinds()};
  return t;
}

/// The keyed kinds in the order messages list them: the ones that may be operands, those that may not, then the
/// combinations (`groups` picks which of the three).
std::vector<const ShapeKind*> keyed_kinds(std::array<bool, 3> groups = {true, true, true}) {
  std::vector<const ShapeKind*> listed;
  for (int group = 0; group < 3; ++group)
    for (const auto& name : shape_kind_names()) {
      const ShapeKind* k = find_shape_kind(name);
      const int its = k->traits.combination ? 2 : k->traits.not_operand.empty() ? 0 : 1;
      if (k->keyed && its == group && groups[static_cast<std::size_t>(group)]) listed.push_back(k);
    }
  return listed;
}

std::vector<std::string> names_of(const std::vector<const ShapeKind*>& kinds) {
  std::vector<std::string> names;
  names.reserve(kinds.size());
  for (const auto* k : kinds) names.push_back(k->name);
  return names;
}

/// "a, b, c or d"
std::string either(const std::vector<std::string>& items) {
  if (items.size() < 2) return fmt::format("{}", fmt::join(items, ""));
  return fmt::format("{} or {}", fmt::join(items.begin(), items.end() - 1, ", "), items.back());
}

/// The kind named by `type` at `value`, checked against the dimension.
const ShapeKind& typed_kind(const io::YamlReader& reader, const io::YamlValue& type, int dimension) {
  const std::string name = reader.string(type);
  std::vector<std::string> valid;
  for (const auto& n : shape_kind_names()) {
    const ShapeKind* k = find_shape_kind(n);
    if (!k->keyed && k->traits.dimensions[static_cast<std::size_t>(dimension - 1)]) valid.push_back(n);
  }
  const ShapeKind* kind = find_shape_kind(name);
  if (!kind || kind->keyed || std::find(valid.begin(), valid.end(), name) == valid.end()) {
    const bool elsewhere = kind && !kind->keyed;
    reader.fail(
        type, fmt::format("{} '{}'{}; valid types in {}D: {} (or {})", elsewhere ? "shape type" : "unknown shape type",
                          name, elsewhere ? fmt::format(" is not available in {}D", dimension) : "", dimension,
                          fmt::join(valid, ", "), fmt::join(names_of(keyed_kinds({true, false, true})), ", ")));
  }
  return *kind;
}

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

}  // namespace

void register_shape_kind(ShapeKind kind) { shape_table().add(std::move(kind)); }

const ShapeKind* find_shape_kind(std::string_view name) { return shape_table().find(name); }

std::vector<std::string> shape_kind_names() { return shape_table().names(); }

const ShapeKind& shape_kind(const ShapeDescription& shape) {
  const ShapeKind* kind = find_shape_kind(shape.kind);
  if (!kind) throw std::logic_error("body shape of unregistered kind '" + shape.kind + "'");
  return *kind;
}

ShapeDescription read_body_shape(const io::YamlReader& reader, const io::YamlValue& value,
                                 const ShapeContext& context) {
  const io::YamlMap map = reader.map(value);
  ShapeDescription shape;
  shape.where = reader.location(value.mark);
  const auto keyed = keyed_kinds();
  std::vector<std::string> given;
  if (map.find("type")) given.push_back("type");
  for (const auto* k : keyed)
    if (map.find(k->name)) given.push_back(k->name);
  if (given.empty()) map.required("type", "key", fmt::format(" (or one of {})", fmt::join(names_of(keyed), ", ")));
  if (given.size() > 1) {
    std::vector<std::string> nouns{"a type"}, own;
    for (const auto* k : keyed_kinds({true, false, true})) nouns.push_back(k->noun);
    for (const auto* k : keyed_kinds({false, true, false})) own.push_back(k->noun);
    reader.fail(*map.find(given[1]),
                fmt::format("a shape is either {}; this one has both {} and {}{}", either(nouns), given[0], given[1],
                            own.empty() ? "" : fmt::format(" ({} is a shape of its own too)", either(own))));
  }
  const ShapeKind& kind =
      given[0] == "type" ? typed_kind(reader, *map.find("type"), context.dimension) : *find_shape_kind(given[0]);
  if (!context.whole_shape && !kind.traits.not_operand.empty())
    reader.fail(*map.find(given[0]), kind.traits.not_operand);
  shape.kind = kind.name;
  shape.spec = kind.parse(reader, map, context);
  return shape;
}

std::optional<ShapeBoundingBox> shape_bounds(const ShapeDescription& shape, int dimension) {
  const ShapeKind& kind = shape_kind(shape);
  if (!kind.bounds) return std::nullopt;
  return kind.bounds(shape.spec, dimension);
}

std::string shape_file(const ShapeDescription& shape) {
  const ShapeKind& kind = shape_kind(shape);
  return kind.file ? kind.file(shape.spec) : "";
}

template <int Dim>
std::unique_ptr<Region<Dim>> make_shape_region(const ShapeDescription& shape, std::vector<std::string>* warnings) {
  const ShapeKind& kind = shape_kind(shape);
  const auto maker = kind.template region<Dim>();
  if (!maker) throw std::logic_error(fmt::format("body shape kind '{}' has no region in {}D", kind.name, Dim));
  return maker(shape.spec, warnings);
}

namespace {

/// A file of a kind with a `scale` (a mesh: its coordinates carry no unit) drawn in millimetres in a metre scene is
/// 1000 times too large: when the shape is more than 20 times the grid's size, the refusal says so (a part of a
/// fiftieth of the grid drawn in millimetres is 20 times it; a shape in metres that large is a mistake of another
/// kind, and the hint asks rather than asserts).
template <int Dim>
std::string millimetre_hint(const ShapeKind& kind, const Box<Dim>& box, const GridGeometry<Dim>& grid) {
  if (!io::find_key(kind.keys, "scale")) return "";
  Real ratio = 0;
  for (int d = 0; d < Dim; ++d) ratio = std::max(ratio, (box.hi[d] - box.lo[d]) / (grid.upper()[d] - grid.origin[d]));
  if (!(ratio > 20)) return "";
  return fmt::format(
      "; the shape is {:.3g} times the grid's size: if the file's coordinates are millimetres, give "
      "the shape `scale: 1.0e-3`",
      ratio);
}

}  // namespace

template <int Dim>
ParticleSeeds<Dim> fill_shape(const ShapeDescription& shape, const GridGeometry<Dim>& grid,
                              const std::array<int, 3>& particles_per_cell, std::vector<std::string>* warnings,
                              std::optional<bool> exact) {
  const ShapeKind& kind = shape_kind(shape);
  const auto own_fill = kind.template filler<Dim>();
  if (!kind.template region<Dim>()) {  // particles of its own only (a particle file)
    if (auto own = own_fill ? own_fill(shape.spec, grid) : std::nullopt) return std::move(*own);
    throw std::logic_error(fmt::format("body shape kind '{}' has neither a region nor a fill in {}D", kind.name, Dim));
  }
  const auto region = make_shape_region<Dim>(shape, warnings);
  const Box<Dim> box = region->bounds();
  const Vec<Dim> upper = grid.upper();
  constexpr const char* axis_names[3] = {"x", "y", "z"};
  for (int d = 0; d < Dim; ++d) {
    const Real tolerance = 1e-9 * (upper[d] - grid.origin[d]);
    const bool clipped_at_axis = d == 0 && grid.coordinates == Coordinates::axisymmetric;  // r < 0 is not filled
    if ((box.lo[d] < grid.origin[d] - tolerance && !clipped_at_axis) || box.hi[d] > upper[d] + tolerance)
      throw ShapeError(shape_file(shape),
                       fmt::format("lies outside the grid: on axis {} it spans [{:.6g}, {:.6g}] m, the grid "
                                   "[{:.6g}, {:.6g}] m{}",
                                   axis_names[d], box.lo[d], box.hi[d], grid.origin[d], upper[d],
                                   millimetre_hint<Dim>(kind, box, grid)));
  }
  if (own_fill)  // after the region's checks (an image whose pixels become particles)
    if (auto own = own_fill(shape.spec, grid)) return std::move(*own);
  return fill_region<Dim>(*region, grid, particles_per_cell, exact.value_or(kind.traits.exact_by_default));
}

std::string read_shape_file(const io::YamlReader& reader, const io::YamlValue& value, const std::string& scene_file,
                            const std::vector<std::string>& extensions, std::string_view what) {
  const std::string name = reader.name(value);
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(scene_file).parent_path() / path;
  const std::string extension = lower_case(path.extension().string());
  if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end())
    reader.fail(value, fmt::format("unsupported {} format '{}' of '{}'; supported: {}", what, extension, name,
                                   fmt::join(extensions, ", ")));
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    reader.fail(value, fmt::format("{} file '{}' not found (looked for {})", what, name, path.string()));
  return path.lexically_normal().string();
}

template std::unique_ptr<Region<1>> make_shape_region<1>(const ShapeDescription&, std::vector<std::string>*);
template std::unique_ptr<Region<2>> make_shape_region<2>(const ShapeDescription&, std::vector<std::string>*);
template std::unique_ptr<Region<3>> make_shape_region<3>(const ShapeDescription&, std::vector<std::string>*);
template ParticleSeeds<1> fill_shape<1>(const ShapeDescription&, const GridGeometry<1>&, const std::array<int, 3>&,
                                        std::vector<std::string>*, std::optional<bool>);
template ParticleSeeds<2> fill_shape<2>(const ShapeDescription&, const GridGeometry<2>&, const std::array<int, 3>&,
                                        std::vector<std::string>*, std::optional<bool>);
template ParticleSeeds<3> fill_shape<3>(const ShapeDescription&, const GridGeometry<3>&, const std::array<int, 3>&,
                                        std::vector<std::string>*, std::optional<bool>);

}  // namespace mpm
