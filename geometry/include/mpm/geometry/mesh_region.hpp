#pragma once
/// \file mesh_region.hpp
/// Bodies from CAD surface meshes (STL ASCII or binary, OBJ, OFF, PLY), read with CGAL. The mesh must be
/// a closed, manifold, not self-intersecting triangle (or polygon) surface; a mesh turned inside out is
/// repaired with a warning. The file's coordinates are scaled, rotated (about x, then y, then z) and
/// translated as the shape says. Inside test: CGAL's Side_of_triangle_mesh on an AABB tree; the exact
/// volume is CGAL's polygon-mesh volume.

#include <memory>
#include <string>
#include <vector>

#include "mpm/geometry/file_shapes.hpp"
#include "mpm/geometry/region.hpp"

namespace mpm::geometry {

/// What was read (for reports and tests).
struct MeshSummary {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  Real volume = 0;  ///< m^3, after the transform
};

/// The 3D region inside the mesh of `shape.file`. Throws GeometryError naming the file and the problem.
std::unique_ptr<Region<3>> make_mesh_region(const MeshShape& shape, std::vector<std::string>* warnings,
                                            MeshSummary* summary = nullptr);

/// The 2D region cut from the mesh by the plane z = *shape.section (after the transform): the polygon
/// loops of the section, even-odd inside. Throws GeometryError when the plane misses the mesh.
std::unique_ptr<Region<2>> make_mesh_section(const MeshShape& shape, std::vector<std::string>* warnings);

}  // namespace mpm::geometry
