// What the kinds share: the allowed keys of a typed kind, and the straight axis of a cylinder or a tube (its keys,
// its reading, its bounding box).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "kinds.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::shapes {

std::vector<std::string> typed_keys(const std::vector<io::KeySpec>& keys) {
  std::vector<std::string> names{"type"};
  for (const auto& k : keys) names.push_back(k.name);
  return names;
}

std::vector<io::KeySpec> shape_axis_keys(const std::string& what) {
  using io::KeyType;
  return {
      {.name = "axis",
       .type = KeyType::choice,
       .choices = {"x", "y", "z"},
       .default_value = std::string("z"),
       .description = "the " + what + "'s axis: `x`, `y`, `z` or any direction `[ax, ay, az]` (a non-zero vector)",
       .type_text = "string, or list of 3 numbers"},
      {.name = "length",
       .type = KeyType::number,
       .unit = "m",
       .range = io::Range::above(0),
       .required = true,
       .description = "the " + what + "'s length along its axis from the base"},
  };
}

ShapeAxis read_shape_axis(const io::YamlReader& reader, const io::YamlMap& map) {
  ShapeAxis a;
  if (const auto axis = map.find("axis")) {
    if (axis->node.IsSequence()) {
      a.direction = reader.vector(*axis, 3, io::Range::any(), "");
      const double norm = std::hypot(a.direction[0], a.direction[1], a.direction[2]);
      if (norm == 0) reader.fail(*axis, "the axis direction must not be the zero vector");
      for (auto& component : a.direction) component /= norm;
      a.axis = -1;
      for (int d = 0; d < 3; ++d)
        if (std::abs(a.direction[d]) == 1 && a.direction[d] > 0) a.axis = d;
    } else {
      const std::vector<std::string> names{"x", "y", "z"};
      if (!axis->node.IsScalar() || std::find(names.begin(), names.end(), axis->node.Scalar()) == names.end())
        reader.fail(*axis, fmt::format("invalid value {}; valid values: x, y, z or a direction [ax, ay, az]",
                                       io::describe(axis->node)));
      a.axis = axis->node.Scalar()[0] - 'x';
    }
  }
  if (a.axis >= 0) {
    a.direction = {0, 0, 0};
    a.direction[a.axis] = 1;
  }
  a.length = reader.number(map.required("length"), io::Range::above(0), "m");
  return a;
}

ShapeBoundingBox cylinder_bounds(const std::array<double, 3>& center, double radius, const ShapeAxis& axis) {
  ShapeBoundingBox box{{0, 0, 0}, {0, 0, 0}};
  for (int d = 0; d < 3; ++d) {  // the end disks reach r sqrt(1 - a_d^2) around the base and the top centre
    const double a = axis.direction[d], reach = radius * std::sqrt(std::max(0.0, 1 - a * a));
    box.first[d] = std::min(center[d], center[d] + axis.length * a) - reach;
    box.second[d] = std::max(center[d], center[d] + axis.length * a) + reach;
  }
  return box;
}

}  // namespace mpm::shapes
