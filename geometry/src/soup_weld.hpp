#pragma once
// Internal to geometry/src: the `weld` of a mesh shape (mesh_kind.cpp), merging the points of a polygon soup that lie
// within a tolerance of one another, so that a mesh whose triangles were written with slightly different copies of
// their shared corners (an STL exported in single precision, a mesh stitched by hand) becomes closed.
#include <cstddef>
#include <vector>

#include "surface_mesh_io.hpp"

namespace mpm::geometry::detail {

/// Merges the points closer than `tolerance` to another (a chain of such points is one group), each group into the
/// mean of its points, and renumbers the polygons. Returns how many points were removed. Exactly repeated points
/// need no tolerance: repair_polygon_soup merges them.
std::size_t weld_soup_points(std::vector<Point3>& points, std::vector<std::vector<std::size_t>>& polygons,
                             double tolerance);

}  // namespace mpm::geometry::detail
