// `grid.coordinates` (docs/scene-reference.md, grid): the axisymmetric rules. In 2D only; the grid starts on the
// axis (origin x = 0) and its face x_min is the axis, a symmetry line whose radial velocity is held at 0 here,
// so no other condition may be written on it.
#include <fmt/format.h>

#include "mpm/boundary/face_condition_kind.hpp"
#include "sections.hpp"

namespace mpm::sections {

void read_coordinates(const YamlReader& reader, const YamlMap& map, int dimension, GridDescription& grid) {
  const auto key = map.find("coordinates");
  if (!key) return;
  grid.coordinates = reader.choice<Coordinates>(*key);
  if (grid.coordinates != Coordinates::axisymmetric) return;
  if (dimension != 2)
    reader.fail(*key, fmt::format("axisymmetric coordinates are 2D (x = r, y = z); this scene is {}D", dimension));
  if (grid.origin[0] != 0)
    reader.fail(*map.find("origin"), fmt::format("an axisymmetric grid starts on the axis: origin x (the radius) must "
                                                 "be 0, got {:g}",
                                                 grid.origin[0]));
  if (const auto boundary = map.find("boundary"))
    if (const auto axis = reader.map(*boundary).find("x_min"))
      if (!(axis->node.IsScalar() && axis->node.Scalar() == "slip"))
        reader.fail(*axis,
                    "x_min is the axis of an axisymmetric grid, a symmetry line (radial velocity 0, set "
                    "automatically): it takes no other condition (write slip or nothing)");
  // the axis: slip, as if written
  grid.boundary[0] = read_face_condition(reader, io::YamlValue{YAML::Node("slip"), key->path, key->mark},
                                         FaceContext{dimension, 0, grid.extent});
}

}  // namespace mpm::sections
