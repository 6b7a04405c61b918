#pragma once
/// \file cubic_bspline.hpp
/// Cubic B-spline with the boundary-modified functions of the review (§3.4, eqs 3.18-3.21), so that the
/// grid has the same n+1 nodes as the hat grid and partition of unity holds up to the box faces.
/// Node types per axis: 1 on a face, 2 one cell inside the lower face, 4 one cell inside the upper face,
/// 3 elsewhere (the uniform cubic). Type 4 is the mirror image of type 2.

#include <algorithm>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm {

struct CubicBSpline {
  static constexpr const char* name = "cubic_bspline";
  static constexpr int support = 4;
  static constexpr int slab_cells = 5;  // a particle in cell c reaches nodes c-2..c+3 near the faces
  /// Nodes a slab [sT, (s+1)T) of cells reaches on its axis: [sT - below, (s+1)T - 1 + above] (halo of a
  /// distributed run, tile_halo.hpp; test ShapeFunctionProperties.SlabThickness).
  static constexpr int slab_reach_below = 2, slab_reach_above = 3;
  static constexpr int min_cells = 4;
  static constexpr bool axisymmetric = true;  ///< usable as it is on an axisymmetric grid (review Remark 42)

  /// Type 1, eq. 3.18 (symmetric in r).
  static inline void boundary(Real r, Real& w, Real& dw) {
    const Real a = std::abs(r), s = r < 0 ? -1 : 1;
    if (a <= 1) {
      w = a * a * a / 6 - a + 1;
      dw = s * (a * a / 2 - 1);
    } else if (a <= 2) {
      const Real b = 2 - a;
      w = b * b * b / 6;
      dw = -s * b * b / 2;
    } else {
      w = dw = 0;
    }
  }
  /// Type 3, eq. 3.20 (the uniform cubic B-spline).
  static inline void interior(Real r, Real& w, Real& dw) {
    const Real a = std::abs(r), s = r < 0 ? -1 : 1;
    if (a <= 1) {
      w = a * a * a / 2 - a * a + Real(2) / 3;
      dw = s * (Real(1.5) * a * a - 2 * a);
    } else if (a <= 2) {
      const Real b = 2 - a;
      w = b * b * b / 6;
      dw = -s * b * b / 2;
    } else {
      w = dw = 0;
    }
  }
  /// Type 2, eq. 3.19: the node one cell inside the lower face.
  static inline void near_lower(Real r, Real& w, Real& dw) {
    if (r < -1 || r > 2) {
      w = dw = 0;
    } else if (r <= 0) {
      w = -r * r * r / 3 - r * r + Real(2) / 3;
      dw = -r * r - 2 * r;
    } else {
      interior(r, w, dw);
    }
  }

  static inline void evaluate(Real xi, int nodes, int& base, Real* w, Real* dw) {
    // Particles are inside the box (the guard checks it), but (x - origin)/h of a particle on the
    // upper face can exceed nodes - 1 by an ulp, where the face functions would be read outside.
    xi = std::clamp<Real>(xi, 0, nodes - 1);
    const int cell = std::clamp(static_cast<int>(std::floor(xi)), 0, nodes - 2);
    base = std::clamp(cell - 1, 0, nodes - 4);
    for (int k = 0; k < support; ++k) {
      const int node = base + k;
      const Real r = xi - node;
      if (node == 0) {
        boundary(r, w[k], dw[k]);
      } else if (node == nodes - 1) {
        // Mirrored, so that a particle exactly on the upper face takes the interior side of the kink at
        // r = 0 (boundary() alone would take the outer side there: gradients summing to -2).
        boundary(-r, w[k], dw[k]);
        dw[k] = -dw[k];
      } else if (node == 1) {
        near_lower(r, w[k], dw[k]);
      } else if (node == nodes - 2) {
        near_lower(-r, w[k], dw[k]);  // type 4 = mirrored type 2 (eq. 3.21)
        dw[k] = -dw[k];
      } else {
        interior(r, w[k], dw[k]);
      }
    }
  }
};

}  // namespace mpm
