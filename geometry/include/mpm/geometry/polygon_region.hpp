#pragma once
/// \file polygon_region.hpp
/// Polygonal 2D regions are the core's (mpm/body_shape/polygon_region.hpp): mesh sections and the conforming
/// triangle meshes use them.

#include "mpm/body_shape/polygon_region.hpp"
#include "mpm/geometry/region.hpp"

namespace mpm::geometry {

using mpm::polygon_loops;
using mpm::PolygonRegion;
using mpm::signed_area;

}  // namespace mpm::geometry
