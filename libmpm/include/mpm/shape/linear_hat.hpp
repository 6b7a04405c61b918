#pragma once
/// \file linear_hat.hpp
/// Linear hat functions (review eqs 3.1-3.3): N(r) = 1 - |r| on |r| <= 1, r = (x - x_I)/h.
/// C0 across cells, hence the cell-crossing error (review §3.2); cheapest and the default.

#include <algorithm>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm {

struct LinearHat {
  static constexpr const char* name = "linear";
  static constexpr int support = 2;     ///< nodes per axis that can be non-zero
  static constexpr int slab_cells = 2;  ///< slab thickness for the race-free scatter (>= nodes reached - 1)
  /// Nodes a slab [sT, (s+1)T) of cells reaches on its axis: [sT - below, (s+1)T - 1 + above] (halo of a
  /// distributed run, tile_halo.hpp; test ShapeFunctionProperties.SlabThickness).
  static constexpr int slab_reach_below = 0, slab_reach_above = 1;
  static constexpr int min_cells = 1;         ///< cells an axis needs
  static constexpr bool axisymmetric = true;  ///< usable as it is on an axisymmetric grid (review Remark 42)
  static constexpr bool multilinear = true;   ///< the multilinear functions of one cell (shape_multilinear)

  /// Weights and derivatives (per unit of the normalised coordinate) of the `support` nodes starting at
  /// `base` on one axis. `xi` = (x - origin)/h; `nodes` = node count on this axis. A particle exactly on
  /// a node belongs to the cell above it (the last node belongs to the last cell).
  static inline void evaluate(Real xi, int nodes, int& base, Real* w, Real* dw) {
    base = std::clamp(static_cast<int>(std::floor(xi)), 0, nodes - 2);
    const Real r = xi - base;
    w[0] = 1 - r;
    w[1] = r;
    dw[0] = -1;
    dw[1] = 1;
  }
};

}  // namespace mpm
