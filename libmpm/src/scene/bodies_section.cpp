// `bodies:` (docs/scene-reference.md, bodies): material, shape (read through its kind, body_shape/shape_kind.hpp),
// particles per cell, initial velocity, volume; a shape that makes several bodies (an image with `labels:`) becomes
// one body each.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/core/closest_name.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/scene_limits.hpp"
#include "mpm/scene/spec_map.hpp"
#include "sections.hpp"

namespace mpm {

const std::vector<io::KeySpec>& body_keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> keys{
      {.name = "name",
       .type = KeyType::name,
       .absent = "`body<i>` (`i` = position in the list, from 0)",
       .description = "the body's name in messages, histories and the contact section",
       .allowed_text = "non-empty; names must be unique"},
      {.name = "material",
       .type = KeyType::name,
       .required = true,
       .description = "the material the body is made of",
       .allowed_text = "a key of `materials`"},
      {.name = "shape",
       .type = KeyType::map,
       .required = true,
       .description = "what the particles fill, see [bodies[].shape](#bodiesshape)"},
      {.name = "particles_per_cell",
       .type = KeyType::integer,
       .range = io::Range::closed(1, max_particles_per_cell),
       .default_value = 2.0,
       .absent = "2 on every axis",
       .description = "particles per cell on each axis (see [Limits](#limits))",
       .type_text = "integer, or list of `dimension` integers"},
      {.name = "velocity",
       .type = KeyType::list,
       .unit = "m/s",
       .default_value = std::string("0"),
       .absent = "zeros",
       .description = "initial velocity, one component per axis",
       .type_text = "list of `dimension` numbers or expressions of `x`, `y`, `z`"},
      {.name = "domains",
       .type = KeyType::choice,
       .choices = {"lattice", "conforming"},
       .default_value = std::string("lattice"),
       .description = "the CPDI particle elements (see below)"},
      {.name = "volume",
       .type = KeyType::choice,
       .choices = {"lattice", "exact"},
       .absent = "the shape kind's: `exact` for `polygon`, `mesh`, `image`; `lattice` otherwise",
       .description = "the particles' volumes: `lattice`, each its sub-cell's; `exact`, the shape's exact volume "
                      "shared equally (shape kinds whose volume is known, see below)"},
  };
  return keys;
}

namespace sections {
namespace {

/// Fails unless the shape's bounding box (when the description knows it) lies inside the grid. Axisymmetric: a
/// shape may cross the axis (its part at r < 0 is not filled: a disk centred on the axis is a sphere).
void check_inside_grid(const YamlReader& reader, const YamlValue& shape, const BodyDescription& body, int dimension,
                       const GridDescription& grid) {
  const auto box = shape_bounds(body.shape, dimension);
  for (int d = 0; box && d < dimension; ++d) {
    const auto& [lo, hi] = *box;
    const double grid_lo = grid.origin[d], grid_hi = grid.origin[d] + grid.extent[d];
    const double tolerance = geometric_tolerance * grid.extent[d];
    const bool clipped_at_axis = d == 0 && grid.coordinates == Coordinates::axisymmetric;
    if ((lo[d] < grid_lo - tolerance && !clipped_at_axis) || hi[d] > grid_hi + tolerance)
      reader.fail(shape, fmt::format("body '{}' lies outside the grid: on axis {} it spans [{:.6g}, {:.6g}] m, the "
                                     "grid [{:.6g}, {:.6g}] m",
                                     body.name, axis_names[d], lo[d], hi[d], grid_lo, grid_hi));
  }
}

/// `volume:` against the shape's kind: `exact` needs a kind whose volume is known; cartesian coordinates only (an
/// axisymmetric body's particle volumes are the rings of their lattice sub-cells).
bool read_volume(const io::SpecMap& map, const ShapeDescription& shape, const SceneDescription& scene) {
  const ShapeTraits& traits = shape_kind(shape).traits;
  const auto value = map.find("volume");
  if (!value) return traits.exact_by_default;
  const bool exact = map.choice("volume") == "exact";
  if (exact && !traits.exact_volume) {
    std::vector<std::string> known;
    for (const auto& name : shape_kind_names())
      if (find_shape_kind(name)->traits.exact_volume) known.push_back(name);
    map.reader().fail(*value, fmt::format("volume: exact needs a shape whose volume is known ({}); {} has none",
                                          fmt::join(known, ", "), shape_kind(shape).noun));
  }
  if (exact && scene.grid.coordinates == Coordinates::axisymmetric)
    map.reader().fail(*value,
                      "volume: exact is for cartesian coordinates; in an axisymmetric run each particle's volume is "
                      "the ring its lattice sub-cell sweeps about the axis");
  return exact;
}

/// `bodies` receives the bodies of a shape that makes several (suffix of the name and shape description each).
BodyDescription read_body(const YamlReader& reader, const YamlValue& value, std::size_t index,
                          const SceneDescription& scene, std::vector<std::pair<std::string, std::any>>& bodies) {
  const int dimension = scene.dimension;
  const io::SpecMap map(reader, value, body_keys());
  BodyDescription body;
  body.where = reader.location(value.mark);
  body.name = fmt::format("body{}", index);
  if (const auto name = map.find("name")) body.name = reader.name(*name);

  const YamlValue material = map.required("material");
  body.material = reader.string(material);
  if (!scene.materials.count(body.material)) {
    std::vector<std::string> defined;
    for (const auto& [name, description] : scene.materials) defined.push_back(name);
    reader.fail(material, fmt::format("unknown material '{}'{}; defined materials: {}", body.material,
                                      did_you_mean(body.material, defined), fmt::join(defined, ", ")));
  }

  const YamlValue shape = map.required("shape");
  body.shape = read_body_shape(reader, shape, {.dimension = dimension, .scene_file = scene.file, .bodies = &bodies});
  check_inside_grid(reader, shape, body, dimension, scene.grid);

  body.particles_per_cell = {1, 1, 1};
  const io::KeySpec& ppc_spec = map.spec("particles_per_cell");
  if (const auto ppc = map.find("particles_per_cell")) {
    const auto counts = reader.per_axis(*ppc, dimension, "integers");
    for (int d = 0; d < dimension; ++d) {
      body.particles_per_cell[d] = reader.integer(counts[d], static_cast<int>(ppc_spec.range.lower));
      if (!ppc_spec.range.contains(body.particles_per_cell[d]))
        reader.fail(counts[d], fmt::format("at most {} particles per cell on an axis, got {} (the memory a body "
                                           "needs is checked against the machine's before it is filled)",
                                           ppc_spec.range.upper, body.particles_per_cell[d]));
    }
  } else {
    for (int d = 0; d < dimension; ++d) body.particles_per_cell[d] = static_cast<int>(ppc_spec.default_number());
  }

  body.velocity.fill(map.spec("velocity").default_text());
  if (const auto velocity = map.find("velocity")) {
    const auto components = reader.list(*velocity, dimension, "components");
    for (int d = 0; d < dimension; ++d) body.velocity[d] = reader.expression(components[d], {"x", "y", "z"}, "m/s");
  }
  body.domains = map.choice("domains");
  body.exact_volume = read_volume(map, body.shape, scene);
  return body;
}

}  // namespace

std::vector<BodyDescription> read_bodies(const YamlReader& reader, const YamlValue& value,
                                         const SceneDescription& scene) {
  const auto items = reader.list(value, std::nullopt, "bodies");
  if (items.empty()) reader.fail(value, "at least one body is required");
  std::vector<BodyDescription> bodies;
  std::map<std::string, int> first_line;  // body name -> line of its definition
  for (std::size_t i = 0; i < items.size(); ++i) {
    std::vector<std::pair<std::string, std::any>> several;
    const BodyDescription read = read_body(reader, items[i], i, scene, several);
    std::vector<BodyDescription> expanded{read};
    if (!several.empty()) {  // a shape that makes several bodies (an image with `labels:`), named <name>_<suffix>
      expanded.clear();
      for (auto& [suffix, spec] : several) {
        BodyDescription body = read;
        body.name = fmt::format("{}_{}", read.name, suffix);
        body.shape.spec = std::move(spec);
        expanded.push_back(std::move(body));
      }
    }
    for (auto& body : expanded) {
      if (const auto it = first_line.find(body.name); it != first_line.end()) {
        const auto name = reader.map(items[i]).find("name");
        reader.fail(name ? *name : items[i],
                    fmt::format("duplicate body name '{}' (first used at line {})", body.name, it->second));
      }
      first_line[body.name] = body.where.line;
      bodies.push_back(std::move(body));
    }
  }
  return bodies;
}

}  // namespace sections
}  // namespace mpm
