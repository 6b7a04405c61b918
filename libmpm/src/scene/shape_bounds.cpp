// The bounding box of a shape description (checked against the grid by the body section).
#include <algorithm>
#include <cmath>
#include <tuple>

#include "shapes.hpp"

namespace mpm::sections {
namespace {

/// Union, intersection or difference (the first part: the others only remove from it).
std::optional<Bounds> set_operation_box(const ShapeDescription& shape, int dimension) {
  Bounds box;
  auto& [lo, hi] = box;
  for (std::size_t k = 0; k < shape.parts.size(); ++k) {
    const auto part = bounding_box(shape.parts[k], dimension);
    if (!part) return std::nullopt;
    if (k == 0) {
      std::tie(lo, hi) = *part;
      if (shape.type == "difference") break;
      continue;
    }
    const bool grow = shape.type == "union";
    for (int d = 0; d < dimension; ++d) {
      lo[d] = grow ? std::min(lo[d], part->first[d]) : std::max(lo[d], part->first[d]);
      hi[d] = grow ? std::max(hi[d], part->second[d]) : std::min(hi[d], part->second[d]);
    }
  }
  return box;
}

}  // namespace

std::optional<Bounds> bounding_box(const ShapeDescription& shape, int dimension) {
  if (shape.type == "box") return Bounds{shape.min, shape.max};
  if (shape.type == "mesh" || shape.type == "image" || shape.type == "particles") return std::nullopt;
  if (shape.type == "union" || shape.type == "intersection" || shape.type == "difference")
    return set_operation_box(shape, dimension);
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
  if (shape.type == "polygon") {
    lo = {shape.vertices[0][0], shape.vertices[0][1], 0};
    hi = lo;
    for (const auto& corner : shape.vertices)
      for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], corner[d]), hi[d] = std::max(hi[d], corner[d]);
    return Bounds{lo, hi};
  }
  for (int d = 0; d < dimension; ++d) {  // disk, sphere, cylinder
    lo[d] = shape.center[d] - shape.radius;
    hi[d] = shape.center[d] + shape.radius;
    if (shape.type == "cylinder") {  // center is the base centre; the end disks reach r sqrt(1 - a_d^2)
      const double a = shape.direction[d], reach = shape.radius * std::sqrt(std::max(0.0, 1 - a * a));
      lo[d] = std::min(shape.center[d], shape.center[d] + shape.length * a) - reach;
      hi[d] = std::max(shape.center[d], shape.center[d] + shape.length * a) + reach;
    }
  }
  return Bounds{lo, hi};
}

}  // namespace mpm::sections
