#pragma once
/// \file node_volume.hpp
/// The volume a node stands for, V_I = ∫ φ_I dV over the grid with the linear hat φ_I of node I, and the grid
/// density m_I / V_I. Σ_I φ_I = 1 makes Σ_I V_I the grid's volume, and a body of uniform density ρ that covers a
/// node's support maps m_I = ρ V_I onto it (exactly with hats, to the quadrature of the particles otherwise), so
/// m_I / V_I is a density smoothed over one cell: ρ inside a body, about ρ/2 on its free surface, 0 outside. The
/// grid output writes it (`density`), where a contour at half the fluid's density draws the free surface
/// (physics/fluids/README.md, "Seeing the water").

#include <numbers>

#include "mpm/grid/grid.hpp"

namespace mpm {

/// ∫ φ dr of a 1D hat of width h at node index i of n nodes (i = 0 and n - 1 are grid faces: half a hat).
inline Real hat_length(Real h, int i, int n) { return (i == 0 || i == n - 1) ? h / 2 : h; }

/// ∫ φ r dr of the radial hat of node i (r_i = i h) of n nodes, the axis at r = 0: h²/6 on the axis,
/// r_i h inside, R h/2 − h²/6 at the outer face r = R (docs/theory.md §14: the revolved volume 2π r dA).
inline Real hat_moment(Real h, int i, int n) {
  const Real r = i * h;
  if (i == 0) return h * h / 6;
  if (i == n - 1) return r * h / 2 - h * h / 6;
  return r * h;
}

/// V_I = ∫ φ_I dV (m³; m² in 2D, m in 1D): Cartesian Π_d ∫ φ dx_d; axisymmetric 2π ∫ φ r dr ∫ φ dz, the
/// revolved volume in which the particles' volumes and masses are counted.
template <int Dim>
Real node_volume(const GridGeometry<Dim>& g, Index node) {
  const auto ijk = g.node_indices(node);
  Real v = 1;
  for (int d = 0; d < Dim; ++d) {
    if (d == 0 && g.coordinates == Coordinates::axisymmetric)
      v *= 2 * std::numbers::pi * hat_moment(g.h[0], ijk[0], g.nodes[0]);
    else
      v *= hat_length(g.h[d], ijk[d], g.nodes[d]);
  }
  return v;
}

}  // namespace mpm
