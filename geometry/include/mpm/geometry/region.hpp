#pragma once
/// \file region.hpp
/// The regions bodies are filled from are the core's (mpm/body_shape/region.hpp); a shape's region comes from its
/// kind (mpm/body_shape/shape_kind.hpp), the primitives' from libmpm, meshes' and images' from this library.

#include <memory>
#include <string>
#include <vector>

#include "mpm/body_shape/region.hpp"
#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::geometry {

using mpm::Box;
using mpm::Region;

/// The region of `shape` through its kind (make_shape_region). Files are read here; their problems throw
/// GeometryError; repairs (a mesh turned outside in) are appended to `warnings`.
template <int Dim>
std::unique_ptr<Region<Dim>> make_region(const ShapeDescription& shape, std::vector<std::string>* warnings = nullptr) {
  return make_shape_region<Dim>(shape, warnings);
}

}  // namespace mpm::geometry
