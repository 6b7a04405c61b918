#pragma once
// Internal to geometry/src (includes CGAL): reading, checking and transforming a CAD surface mesh into a
// CGAL Surface_mesh. Used by mesh_region.cpp (inside test, sections) and conforming_domains_3d.cpp (Mesh_3).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <memory>
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
/// the shape's scale, rotation and translation applied (after the checks, so that messages give the file's
/// coordinates), of the shape's `object` or `shell` alone when it names one, its vertices welded when it says.
/// Throws GeometryError naming the file and the problem (and the key for `object` and `shell`); an inside-out or
/// inconsistently oriented mesh is repaired and a warning appended, as is one for several shells or objects merged.
SurfaceMesh load_surface_mesh(const MeshShape& shape, std::vector<std::string>* warnings);

/// CGAL's ray-shooting inside test of a closed triangle mesh, on an AABB tree built on its first query (thread-safe)
/// and kept.
using InsideTest = CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>;

/// A closed mesh with its inside test, shared by the regions made of one mesh (so its tree is built once).
struct ClosedSurface {
  std::shared_ptr<const SurfaceMesh> mesh;
  std::shared_ptr<const InsideTest> inside;  ///< of *mesh
  /// A surface of its own (not shared): a CAD solid's tessellation.
  static ClosedSurface of(SurfaceMesh mesh);
};

/// load_surface_mesh's mesh, read once per process for each content of the file and each shape
/// (surface_mesh_cache.cpp); its warnings are appended at every call (print each once).
ClosedSurface shared_surface_mesh(const MeshShape& shape, std::vector<std::string>* warnings);

/// The closed, manifold, self-intersection-free, outward-oriented triangle mesh of a polygon soup (points in m):
/// duplicated points merged, degenerate faces dropped, orientation repaired (with a warning). Throws GeometryError
/// naming `file` (the file, or the file and the solid it came from) and the problem.
SurfaceMesh close_polygon_soup(const std::string& file, std::vector<Point3> points,
                               std::vector<std::vector<std::size_t>> polygons, std::vector<std::string>* warnings);

/// The region inside a closed mesh (close_polygon_soup's): CGAL's inside test, its volume and exact properties
/// (mass_properties.hpp).
std::unique_ptr<Region<3>> surface_region(SurfaceMesh mesh);

/// Builds a box as a closed triangle mesh (12 triangles, outward).
SurfaceMesh box_mesh(const Box<3>& box);
/// The surface of a mesh region (make_mesh_region), or nullptr for a region of another kind.
const SurfaceMesh* surface_of(const Region<3>& region);

}  // namespace mpm::geometry::detail
