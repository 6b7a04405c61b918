// `dimension:` and `grid:` with its `boundary:` (docs/scene-reference.md, grid).
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "sections.hpp"

namespace mpm::sections {
namespace {

/// A face given as a map: velocity and/or traction components, each an expression of t ("free": none).
void read_face_condition(const YamlReader& reader, const YamlMap::Entry& face, int dimension, FaceBoundary& boundary) {
  const YamlMap condition = reader.map(face.value);
  condition.allow({"velocity", "traction"});
  const auto velocity = condition.find("velocity");
  const auto traction = condition.find("traction");
  if (!velocity && !traction) reader.fail(face.value, "expected velocity: [...] and/or traction: [...]");
  if (velocity) {
    const auto components = reader.list(*velocity, dimension, "components");
    for (int d = 0; d < dimension; ++d) {
      if (components[d].node.IsScalar() && components[d].node.Scalar() == "free") continue;
      boundary.component[d] = reader.expression(components[d], {"t"});
    }
  }
  if (traction) {
    const auto components = reader.list(*traction, dimension, "components");
    for (int d = 0; d < dimension; ++d) {
      if (boundary.component[d])
        reader.fail(components[d],
                    fmt::format("component {} of face {} has both a velocity and a traction", axis_names[d], face.key));
      boundary.traction[d] = reader.expression(components[d], {"t"});
    }
  }
}

void read_boundary(const YamlReader& reader, const YamlValue& value, int dimension, GridDescription& grid) {
  const YamlMap faces = reader.map(value);
  const auto& names = GridDescription::face_names;
  const std::vector<std::string> valid(names.begin(), names.begin() + std::ptrdiff_t{2} * dimension);
  faces.allow(valid, "face", fmt::format(" in {}D", dimension));
  for (const auto& face : faces.entries()) {
    const int index = static_cast<int>(std::find(valid.begin(), valid.end(), face.key) - valid.begin());
    const int normal_axis = index / 2;
    FaceBoundary& boundary = grid.boundary[index];
    boundary.where = reader.location(face.value.mark);
    if (face.value.node.IsMap()) {
      read_face_condition(reader, face, dimension, boundary);
    } else if (face.value.node.IsScalar()) {
      const std::string kind = reader.choice(face.value, {"fixed", "slip", "free"});
      const ComponentConstraint held{std::in_place, "0"};  // the velocity component is 0
      if (kind == "fixed")
        for (int d = 0; d < dimension; ++d) boundary.component[d] = held;
      else if (kind == "slip")
        boundary.component[normal_axis] = held;
    } else {
      reader.fail(face.value, "expected fixed, slip, free or {velocity: [...]}, got " + io::describe(face.value.node));
    }
  }
}

}  // namespace

int read_dimension(const YamlReader& reader, const YamlMap& top) {
  const YamlValue value = top.required("dimension");
  const int dimension = reader.integer(value, std::numeric_limits<int>::min());
  if (dimension < 1 || dimension > 3) reader.fail(value, fmt::format("must be 1, 2 or 3, got {}", dimension));
  return dimension;
}

GridDescription read_grid(const YamlReader& reader, const YamlValue& value, int dimension) {
  const YamlMap map = reader.map(value);
  map.allow({"origin", "extent", "cell_size", "boundary", "coordinates"});
  GridDescription grid;
  if (const auto origin = map.find("origin")) grid.origin = reader.vector(*origin, dimension, Range::any(), "m");
  grid.extent = reader.vector(map.required("extent"), dimension, Range::above(0), "m");
  const auto sizes = reader.per_axis(map.required("cell_size"), dimension, "numbers");
  for (int d = 0; d < dimension; ++d) {
    grid.cell_size[d] = reader.number(sizes[d], Range::above(0), "m");
    const double ratio = grid.extent[d] / grid.cell_size[d];
    const double cells = std::round(ratio);
    if (cells < 1 || std::abs(ratio - cells) > geometric_tolerance * ratio)
      reader.fail(sizes[d], fmt::format("extent {} m on axis {} is not a whole number of cells of {} m "
                                        "(extent / cell_size = {:.10g})",
                                        grid.extent[d], axis_names[d], grid.cell_size[d], ratio));
    if (cells > 1e9) reader.fail(sizes[d], fmt::format("{} cells on axis {} is too many", cells, axis_names[d]));
    grid.cells[d] = static_cast<int>(cells);
  }
  if (const auto boundary = map.find("boundary")) read_boundary(reader, *boundary, dimension, grid);
  read_coordinates(reader, map, dimension, grid);
  return grid;
}

}  // namespace mpm::sections
