#pragma once
// Internal to geometry/src (includes CGAL): reading, checking and transforming a CAD surface mesh into a
// CGAL Surface_mesh. Used by mesh_region.cpp (inside test, sections) and conforming_domains_3d.cpp (Mesh_3).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <string>
#include <vector>

#include "mpm/geometry/file_shapes.hpp"
#include "mpm/geometry/region.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::geometry::detail {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;

/// The closed, manifold, self-intersection-free, outward-oriented triangle mesh of `shape.file`, with
/// the shape's scale, rotation and translation applied. Throws GeometryError naming the file and the
/// problem; an inside-out or inconsistently oriented mesh is repaired and a warning appended.
SurfaceMesh load_surface_mesh(const MeshShape& shape, std::vector<std::string>* warnings);

/// Builds a box as a closed triangle mesh (12 triangles, outward).
SurfaceMesh box_mesh(const Box<3>& box);
/// The surface of a mesh region (make_mesh_region), or nullptr for a region of another kind.
const SurfaceMesh* surface_of(const Region<3>& region);

}  // namespace mpm::geometry::detail
