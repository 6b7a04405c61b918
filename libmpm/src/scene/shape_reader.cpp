// A body's `shape:`: which kind it is (a `type:`, a mesh, an image or a set operation of shapes), and the
// primitives box, disk, sphere and cylinder.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "sections.hpp"
#include "shapes.hpp"

namespace mpm::sections {
namespace {

/// Shape types per dimension (index 1..3), given with `type:`.
const std::vector<std::string> shape_types[4] = {
    {}, {"box"}, {"box", "disk", "polygon"}, {"box", "sphere", "cylinder"}};

void read_box(const YamlReader& reader, const YamlMap& map, int dimension, ShapeDescription& shape) {
  map.allow({"type", "min", "max"});
  shape.min = reader.vector(map.required("min"), dimension, Range::any(), "m");
  const YamlValue max = map.required("max");
  shape.max = reader.vector(max, dimension, Range::any(), "m");
  for (int d = 0; d < dimension; ++d)
    if (!(shape.min[d] < shape.max[d]))
      reader.fail(max, fmt::format("max must exceed min on every axis; on axis {}: min {} m, max {} m", axis_names[d],
                                   shape.min[d], shape.max[d]));
}

/// `axis:` x, y, z or any direction [ax, ay, az] (normalised); shape.axis is -1 for an oblique one.
void read_cylinder_axis(const YamlReader& reader, const YamlValue& axis, ShapeDescription& shape) {
  if (axis.node.IsSequence()) {
    shape.direction = reader.vector(axis, 3, Range::any(), "");
    const double norm = std::hypot(shape.direction[0], shape.direction[1], shape.direction[2]);
    if (norm == 0) reader.fail(axis, "the axis direction must not be the zero vector");
    for (auto& component : shape.direction) component /= norm;
    shape.axis = -1;
    for (int d = 0; d < 3; ++d)
      if (std::abs(shape.direction[d]) == 1 && shape.direction[d] > 0) shape.axis = d;
  } else {
    if (!axis.node.IsScalar() || !contains({"x", "y", "z"}, axis.node.Scalar()))
      reader.fail(axis, fmt::format("invalid value {}; valid values: x, y, z or a direction [ax, ay, az]",
                                    io::describe(axis.node)));
    shape.axis = axis.node.Scalar()[0] - 'x';
  }
}

void read_cylinder(const YamlReader& reader, const YamlMap& map, int dimension, ShapeDescription& shape) {
  map.allow({"type", "center", "radius", "axis", "length"});
  shape.center = reader.vector(map.required("center"), dimension, Range::any(), "m");
  shape.radius = reader.number(map.required("radius"), Range::above(0), "m");
  if (const auto axis = map.find("axis")) read_cylinder_axis(reader, *axis, shape);
  if (shape.axis >= 0) {
    shape.direction = {0, 0, 0};
    shape.direction[shape.axis] = 1;
  }
  shape.length = reader.number(map.required("length"), Range::above(0), "m");
}

/// A `type:` shape: box, disk, sphere, cylinder or polygon, as the dimension allows.
void read_typed_shape(const YamlReader& reader, const YamlMap& map, int dimension, const std::string& scene_file,
                      ShapeDescription& shape) {
  const YamlValue type = *map.find("type");
  shape.type = reader.string(type);
  const auto& valid = shape_types[dimension];
  if (!contains(valid, shape.type)) {
    const bool elsewhere =
        shape.type == "disk" || shape.type == "sphere" || shape.type == "cylinder" || shape.type == "polygon";
    reader.fail(type, fmt::format("{} '{}'{}; valid types in {}D: {} (or mesh, image, union, intersection, difference)",
                                  elsewhere ? "shape type" : "unknown shape type", shape.type,
                                  elsewhere ? fmt::format(" is not available in {}D", dimension) : "", dimension,
                                  fmt::join(valid, ", ")));
  }
  if (shape.type == "box") {
    read_box(reader, map, dimension, shape);
  } else if (shape.type == "polygon") {
    read_polygon(reader, map, scene_file, shape);
  } else if (shape.type == "cylinder") {
    read_cylinder(reader, map, dimension, shape);
  } else {  // disk, sphere
    map.allow({"type", "center", "radius"});
    shape.center = reader.vector(map.required("center"), dimension, Range::any(), "m");
    shape.radius = reader.number(map.required("radius"), Range::above(0), "m");
  }
}

}  // namespace

ShapeDescription read_shape(const YamlReader& reader, const YamlValue& value, int dimension,
                            const std::string& scene_file, bool whole_shape, std::vector<double>* labels) {
  const YamlMap map = reader.map(value);
  ShapeDescription shape;
  shape.where = reader.location(value.mark);
  std::vector<std::string> given;
  for (const auto& key :
       std::vector<std::string>{"type", "mesh", "image", "particles", "union", "intersection", "difference"})
    if (map.find(key)) given.push_back(key);
  if (given.empty())
    map.required("type", "key", " (or one of mesh, image, particles, union, intersection, difference)");
  if (given.size() > 1)
    reader.fail(*map.find(given[1]),
                fmt::format("a shape is either a type, a mesh, an image, a union, an intersection or a difference; "
                            "this one has both {} and {} (a particle file is a shape of its own too)",
                            given[0], given[1]));
  const std::string& kind = given[0];
  if (kind == "particles") {
    read_particles(reader, map, scene_file, whole_shape, shape);
  } else if (kind == "mesh") {
    read_mesh(reader, map, dimension, scene_file, shape);
  } else if (kind == "image") {
    read_image(reader, map, dimension, scene_file, whole_shape, shape, labels);
  } else if (kind == "type") {
    read_typed_shape(reader, map, dimension, scene_file, shape);
  } else {  // union, intersection, difference
    map.allow({kind});
    shape.type = kind;
    const YamlValue list = *map.find(kind);
    const auto items = reader.list(list, std::nullopt, "shapes");
    if (items.size() < 2) reader.fail(list, fmt::format("a {} needs a list of at least 2 shapes", kind));
    for (const auto& item : items)
      shape.parts.push_back(read_shape(reader, item, dimension, scene_file, false, nullptr));
  }
  return shape;
}

}  // namespace mpm::sections
