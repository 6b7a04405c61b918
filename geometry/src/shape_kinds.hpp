#pragma once
// geometry's body shape kinds (mpm/body_shape/shape_kind.hpp), one file each; register.cpp registers them.

#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/geometry/file_shapes.hpp"

namespace mpm::geometry {

ShapeKind mesh_kind();   // mesh_kind.cpp
ShapeKind image_kind();  // image_kind.cpp
ShapeKind cad_kind();    // cad_kind.cpp
ShapeKind gmsh_kind();   // gmsh_kind.cpp

}  // namespace mpm::geometry
