#pragma once
/// \file boundary/face.hpp
/// The six faces of the grid box (names: face_names.hpp): the axis and side of a face, and its nodes.
/// Engine layer: knows the grid, not the scene language.

#include <vector>

#include "mpm/boundary/face_names.hpp"
#include "mpm/grid/grid.hpp"

namespace mpm {

/// The axis normal to `face` (0 .. 2 D - 1).
constexpr int face_axis(int face) { return face / 2; }
/// Whether `face` is the upper face of its axis (x_max, y_max, z_max).
constexpr bool is_upper_face(int face) { return face % 2 == 1; }

/// The nodes on `face`, ascending.
template <int Dim>
std::vector<Index> face_nodes(const GridGeometry<Dim>& g, int face) {
  const int axis = face_axis(face);
  const int layer = is_upper_face(face) ? g.nodes[axis] - 1 : 0;
  std::vector<Index> nodes;
  for (Index n = 0; n < g.node_count(); ++n)
    if (g.node_indices(n)[axis] == layer) nodes.push_back(n);
  return nodes;
}

}  // namespace mpm
