#pragma once
/// \file bernstein_quadratic.hpp
/// Quadratic Bernstein functions (review §3.5, eqs 3.22-3.25) on the plain grid: an element is TWO grid
/// cells, so even-index nodes are element vertices and odd-index nodes element mid-points. A Bernstein
/// grid of m elements per axis is a plain grid of 2m cells: the cell count of every axis MUST be even
/// (evaluate assumes it; `cell_multiple` states it for the caller that builds the grid).
///
/// On the element [a, a + E], E = 2h, with s = (x - a)/E in [0, 1] (eq. 3.22, k = 2):
///   left vertex (1 - s)^2,  mid node 2 s (1 - s),  right vertex s^2.
/// Per node, r = (x - x_I)/E (eqs 3.24-3.25, where the review's h is the element size E):
///   vertex node   S(r) = (1 - |r|)^2 for |r| <= 1   ((1 - s)^2 to its right, s^2 to its left);
///   mid node      S(r) = 1/2 - 2 r^2 for |r| <= 1/2 (= 2 s (1 - s) with s = r + 1/2).
/// The review's formulas agree with the element basis (its "1 <= i <= k+1" after 3.22 means 0 <= i <= k).
///
/// Properties: partition of unity; linear reproduction (sum phi_I x_I = x, sum x_I dphi_I = 1) because
/// the mid node is the element centre (a(1-s)^2 + (a + E/2) 2s(1-s) + (a + E)s^2 = a + E s);
/// non-negativity; Kronecker delta at the vertices (the vertex weight is 1 on its vertex, all others 0),
/// not at the mid nodes (1/2 on its own position, 1/4 for each vertex). C-infinity inside an element, only
/// C0 across element boundaries (the review recommends it for TLMPM only).
/// Support: the 3 nodes of the particle's element (base = its left vertex, even). A particle in cell c
/// reaches nodes c..c+2 (c even) or c-1..c+1 (c odd). Slabs of 2 cells coincide with elements, so two
/// same-coloured slabs (elements 2 apart) share no node: slab_cells = 2.

#include <algorithm>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm {

struct BernsteinQuadratic {
  static constexpr const char* name = "bernstein";
  static constexpr int support = 3;
  static constexpr int slab_cells = 2;  // one element; slabs start at node 0, so they align with elements
  /// Nodes a slab [sT, (s+1)T) of cells reaches on its axis: [sT - below, (s+1)T - 1 + above] (halo of a
  /// distributed run, tile_halo.hpp; test ShapeFunctionProperties.SlabThickness).
  static constexpr int slab_reach_below = 0, slab_reach_above = 1;
  static constexpr int min_cells = 2;      // one element
  static constexpr int cell_multiple = 2;  // every axis needs an even number of cells

  /// `nodes` must be odd (an even number of cells). A particle on an element vertex belongs to the
  /// element above it (the last vertex to the last element).
  static inline void evaluate(Real xi, int nodes, int& base, Real* w, Real* dw) {
    const int elements = (nodes - 1) / 2;
    base = 2 * std::clamp(static_cast<int>(std::floor(xi / 2)), 0, elements - 1);
    const Real s = (xi - base) / 2;
    w[0] = (1 - s) * (1 - s);
    w[1] = 2 * s * (1 - s);
    w[2] = s * s;
    // d/dxi = (1/2) d/ds.
    dw[0] = s - 1;
    dw[1] = 1 - 2 * s;
    dw[2] = s;
  }
};

}  // namespace mpm
