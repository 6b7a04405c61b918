#pragma once
// The core's body shape kinds (mpm/body_shape/shape_kind.hpp), one file each in this folder, and their list
// (core_shape_kinds(), the registry's first entries in this order). What several of them share is here too.

#include <array>
#include <deque>
#include <string>
#include <vector>

#include "mpm/body_shape/primitive_shapes.hpp"
#include "mpm/body_shape/shape_kind.hpp"

namespace mpm::shapes {

ShapeKind box_kind();            // box_kind.cpp
ShapeKind disk_kind();           // ball_kinds.cpp
ShapeKind sphere_kind();         // ball_kinds.cpp
ShapeKind cylinder_kind();       // cylinder_kind.cpp
ShapeKind polygon_kind();        // polygon_kind.cpp
ShapeKind ring_kind();           // ring_kind.cpp
ShapeKind particle_file_kind();  // particle_file_kind.cpp
ShapeKind union_kind();          // combination_kinds.cpp
ShapeKind intersection_kind();   // combination_kinds.cpp
ShapeKind difference_kind();     // combination_kinds.cpp

/// The core's kinds in the order the registry lists them (messages and the scene reference follow it).
inline std::deque<ShapeKind> core_shape_kinds() {
  return {box_kind(),  disk_kind(),          sphere_kind(), cylinder_kind(),     polygon_kind(),
          ring_kind(), particle_file_kind(), union_kind(),  intersection_kind(), difference_kind()};
}

/// Axis names for messages, in the order x, y, z.
inline constexpr const char* axis_names[3] = {"x", "y", "z"};

/// The keys `type` plus those of `keys`, in order: what a typed kind's map may hold.
std::vector<std::string> typed_keys(const std::vector<io::KeySpec>& keys);

/// `axis:` (x, y, z or a direction [ax, ay, az], normalised; default z) and `length:` (> 0) of a cylinder or a
/// tube (shape_axis.cpp).
ShapeAxis read_shape_axis(const io::YamlReader& reader, const io::YamlMap& map);
/// The key specs of `axis` and `length`.
std::vector<io::KeySpec> shape_axis_keys(const std::string& what);
/// The bounding box of a circular cylinder of `radius` from the base centre `center` along `axis`.
ShapeBoundingBox cylinder_bounds(const std::array<double, 3>& center, double radius, const ShapeAxis& axis);

template <int Dim>
Vec<Dim> to_vec(const std::array<double, 3>& a) {
  Vec<Dim> v;
  for (int d = 0; d < Dim; ++d) v[d] = a[d];
  return v;
}

}  // namespace mpm::shapes
