#pragma once
/// \file boundary/face_names.hpp
/// The names of the six faces of the grid box, in the order of every per-face array.

#include <array>

namespace mpm {

/// The box faces in the order of every per-face array (`grid.boundary`, `thermal.boundary`, energy.csv's outflow
/// columns): x_min, x_max, y_min, y_max, z_min, z_max. A run of dimension D has the first 2 D.
inline constexpr std::array<const char*, 6> face_names{"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};

}  // namespace mpm
