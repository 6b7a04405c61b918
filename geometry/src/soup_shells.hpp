#pragma once
// Internal to geometry/src: the connected shells of a polygon soup, so that a mesh file of several separate surfaces
// (two parts exported together) is said to be several, and `shell: INDEX` (mesh_kind.cpp) can choose one.
#include <cstddef>
#include <vector>

namespace mpm::geometry::detail {

/// The shell of every polygon: polygons that share a point (directly or through others) are in one shell. Shells are
/// numbered 0, 1, ... in the order of their first polygon. `point_count`: the number of points the polygons index.
std::vector<std::size_t> soup_shells(std::size_t point_count, const std::vector<std::vector<std::size_t>>& polygons);

}  // namespace mpm::geometry::detail
