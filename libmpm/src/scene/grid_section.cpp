// `dimension:` and `grid:` with its `boundary:` (docs/scene-reference.md, grid).
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "mpm/boundary/face_condition_kind.hpp"
#include "sections.hpp"

namespace mpm::sections {
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
