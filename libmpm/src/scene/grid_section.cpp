// `dimension:` and `grid:` with its `boundary:` (docs/scene-reference.md, grid).
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "mpm/boundary/face_condition_kind.hpp"
#include "mpm/core/enum_names.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/spec_map.hpp"
#include "sections.hpp"

namespace mpm {

const std::vector<io::KeySpec>& grid_keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> keys{
      {.name = "origin",
       .type = KeyType::list,
       .unit = "m",
       .absent = "zeros",
       .description = "the grid box's lower corner",
       .type_text = "list of `dimension` numbers",
       .allowed_text = "any"},
      {.name = "extent",
       .type = KeyType::list,
       .unit = "m",
       .range = io::Range::above(0),
       .required = true,
       .description = "the grid box's lengths: the box is `[origin, origin + extent]`",
       .type_text = "list of `dimension` numbers",
       .allowed_text = "each > 0"},
      {.name = "cell_size",
       .type = KeyType::number,
       .unit = "m",
       .range = io::Range::above(0),
       .required = true,
       .description = "the cells' lengths; the number of cells per axis is `extent / cell_size`",
       .type_text = "number, or list of `dimension` numbers",
       .allowed_text = "each > 0; `extent / cell_size` must be a whole number on every axis (within a relative 1e-9)"},
      {.name = "boundary",
       .type = KeyType::named_map,
       .absent = "every face `stop`",
       .description = "per face a condition, see [grid.boundary](#gridboundary)",
       .type_text = "map from faces to conditions",
       .allowed_text = "the faces of the scene's dimension: `x_min`, `x_max`, `y_min`, `y_max`, `z_min`, `z_max`",
       .run_control = true},
      {.name = "coordinates",
       .type = KeyType::choice,
       .choices = enum_names<Coordinates>(),
       .default_value = std::string("cartesian"),
       .description = "`axisymmetric` (2D only): see [grid.coordinates](#gridcoordinates)"},
  };
  return keys;
}

namespace sections {
namespace {

/// `grid.boundary`: per face a condition of a registered kind (mpm/boundary/face_condition_kind.hpp).
void read_boundary(const YamlReader& reader, const YamlValue& value, int dimension, GridDescription& grid) {
  const YamlMap faces = reader.map(value);
  const auto& names = GridDescription::face_names;
  const std::vector<std::string> valid(names.begin(), names.begin() + std::ptrdiff_t{2} * dimension);
  faces.allow(valid, "face", fmt::format(" in {}D", dimension));
  for (const auto& face : faces.entries()) {
    const int index = static_cast<int>(std::find(valid.begin(), valid.end(), face.key) - valid.begin());
    grid.boundary[static_cast<std::size_t>(index)] =
        read_face_condition(reader, face.value, FaceContext{dimension, index, grid.extent});
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
  const io::SpecMap map(reader, value, grid_keys());
  const auto spec = [&](std::string_view key) -> const io::KeySpec& { return map.spec(key); };
  GridDescription grid;
  if (const auto origin = map.find("origin"))
    grid.origin = reader.vector(*origin, dimension, spec("origin").range, spec("origin").unit);
  grid.extent = reader.vector(map.required("extent"), dimension, spec("extent").range, spec("extent").unit);
  const auto sizes = reader.per_axis(map.required("cell_size"), dimension, "numbers");
  for (int d = 0; d < dimension; ++d) {
    grid.cell_size[d] = reader.number(sizes[d], spec("cell_size").range, spec("cell_size").unit);
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
  read_coordinates(reader, map.map(), dimension, grid);
  return grid;
}

}  // namespace sections
}  // namespace mpm
