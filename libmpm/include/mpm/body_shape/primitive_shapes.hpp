#pragma once
/// \file body_shape/primitive_shapes.hpp
/// The plain descriptions of the core's body shape kinds (shape_kind.hpp), what their parsers return in
/// ShapeDescription::spec; one file each in src/body_shape/. Lengths in m.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace mpm {

/// `type: box` (1D, 2D, 3D): the corners, min < max on every axis.
struct BoxShape {
  std::array<double, 3> min{0, 0, 0}, max{0, 0, 0};
};

/// `type: disk` (2D) and `type: sphere` (3D).
struct BallShape {
  std::array<double, 3> center{0, 0, 0};
  double radius = 0;
};

/// A straight axis from a base centre (cylinder, ring in 3D): `axis` x, y or z, or any direction.
struct ShapeAxis {
  int axis = 2;                              ///< 0 = x, 1 = y, 2 = z; -1 = oblique (see direction)
  std::array<double, 3> direction{0, 0, 1};  ///< the axis as a unit vector
  double length = 0;                         ///< along the axis from the base centre
};

/// `type: cylinder` (3D): `center` is the centre of the base.
struct CylinderShape {
  std::array<double, 3> center{0, 0, 0};
  double radius = 0;
  ShapeAxis axis;
};

/// `type: ring` (2D: an annulus; 3D: a tube whose `center` is the centre of its base), inner_radius < outer_radius.
struct RingShape {
  std::array<double, 3> center{0, 0, 0};
  double inner_radius = 0;
  double outer_radius = 0;
  ShapeAxis axis;  ///< 3D only
};

/// `type: polygon` (2D): corners in either orientation, simple, non-zero area.
struct PolygonShape {
  std::vector<std::array<double, 2>> vertices;
};

/// `union`, `intersection`, `difference`: the operands (difference: the first minus the others).
struct CombinedShape {
  std::vector<ShapeDescription> parts;
};

/// `particles: FILE` (.vtu or .csv): a particle set, optionally only the rows of one `body`.
struct ParticleFileShape {
  std::string file;  ///< made relative to the working directory
  std::optional<int> body;
};

}  // namespace mpm
