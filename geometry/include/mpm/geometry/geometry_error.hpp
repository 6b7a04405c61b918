#pragma once
/// \file geometry_error.hpp
/// The exception of geometry input: a mesh or image file that cannot be used (missing, unreadable, open,
/// non-manifold, self-intersecting, empty, a threshold that selects nothing, ...). It is the core's ShapeError
/// (mpm/body_shape/shape_kind.hpp): what() is `FILE: problem`, and `file` and `problem` are kept apart so that the
/// scene builder can report them at the shape's place in the scene.

#include "mpm/body_shape/shape_kind.hpp"

namespace mpm::geometry {

using GeometryError = mpm::ShapeError;

}  // namespace mpm::geometry
