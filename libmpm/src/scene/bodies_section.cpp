// `bodies:` (docs/scene-reference.md, bodies): material, shape (shapes.hpp), particles per cell, initial
// velocity; an image with `labels:` becomes one body per label.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/scene_limits.hpp"
#include "mpm/scene/spec_map.hpp"
#include "sections.hpp"
#include "shapes.hpp"

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
  };
  return keys;
}

namespace sections {
namespace {

/// Fails unless the shape's bounding box (when the description knows it) lies inside the grid. Axisymmetric: a
/// shape may cross the axis (its part at r < 0 is not filled: a disk centred on the axis is a sphere).
void check_inside_grid(const YamlReader& reader, const YamlValue& shape, const BodyDescription& body, int dimension,
                       const GridDescription& grid) {
  const auto box = bounding_box(body.shape, dimension);
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

/// `labels` receives the values of an image shape's `labels:` list (the body is then one body per label).
BodyDescription read_body(const YamlReader& reader, const YamlValue& value, std::size_t index,
                          const SceneDescription& scene, std::vector<double>& labels) {
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
    reader.fail(material,
                fmt::format("unknown material '{}'; defined materials: {}", body.material, fmt::join(defined, ", ")));
  }

  const YamlValue shape = map.required("shape");
  body.shape = read_shape(reader, shape, dimension, scene.file, true, &labels);
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
    for (int d = 0; d < dimension; ++d) body.velocity[d] = reader.expression(components[d], {"x", "y", "z"});
  }
  body.domains = map.choice("domains");
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
    std::vector<double> labels;
    const BodyDescription read = read_body(reader, items[i], i, scene, labels);
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
