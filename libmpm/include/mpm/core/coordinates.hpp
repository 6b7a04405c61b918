#pragma once
/// \file coordinates.hpp
/// The coordinate system of a scene (`grid.coordinates`, docs/scene-reference.md): Cartesian (1D uniaxial
/// strain, 2D plane strain, 3D) or, in 2D only, axisymmetric: x is the radius r >= 0, y the axial z, and every
/// particle stands for the ring it sweeps in a full revolution (axisymmetric.hpp, docs/theory.md §14).
/// The scene picks the system once; the kernels are templates on one of the two tags below, so a Cartesian
/// run compiles to exactly the code it had before the axisymmetric mode existed.

#include <array>
#include <string_view>
#include <utility>

#include "mpm/core/enum_names.hpp"

namespace mpm {

enum class Coordinates { cartesian, axisymmetric };

template <>
struct EnumNames<Coordinates> {
  static constexpr std::array<std::pair<Coordinates, std::string_view>, 2> table{
      {{Coordinates::cartesian, "cartesian"}, {Coordinates::axisymmetric, "axisymmetric"}}};
};

/// Compile-time tags of the coordinate system, the `Coords` parameter of the schemes and kernels.
struct CartesianCoordinates {
  static constexpr bool axisymmetric = false;
};
struct AxisymmetricCoordinates {
  static constexpr bool axisymmetric = true;
};

}  // namespace mpm
