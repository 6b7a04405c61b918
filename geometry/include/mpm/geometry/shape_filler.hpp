#pragma once
/// \file shape_filler.hpp
/// A body's particles from its scene shape are the core's fill_shape (mpm/body_shape/shape_kind.hpp): the region of
/// the shape's kind filled on the grid lattice, or the kind's own particles (an image's `resolution: pixel`).

#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/geometry/primitive_filler.hpp"

namespace mpm::geometry {

using mpm::fill_shape;

}  // namespace mpm::geometry
