#pragma once
/// \file lagrange_quadratic.hpp
/// Quadratic Lagrange (finite-element) functions, the basis of the 1D TLMPM of Nuttall (2025, the "000
/// paper", eq. 28 with n_en = 3 equally spaced abscissae), on the plain grid with the layout of
/// BernsteinQuadratic: an element is TWO grid cells, even-index nodes are element vertices and odd-index
/// nodes element mid-points, and the cell count of every axis MUST be even (`cell_multiple`).
///
/// On the element [a, a + E], E = 2h, with s = (x - a)/E in [0, 1] (xi_k = -1, 0, 1 of eq. 28 mapped to
/// s = 0, 1/2, 1):
///   left vertex (1 - s)(1 - 2s),  mid node 4 s (1 - s),  right vertex s (2s - 1).
/// Per node, r = (x - x_I)/E:
///   vertex node   S(r) = (1 - |r|)(1 - 2|r|) for |r| <= 1;   mid node  S(r) = 1 - 4 r^2 for |r| <= 1/2.
///
/// Properties: partition of unity; quadratic (hence linear) reproduction; Kronecker delta at EVERY node
/// (vertices and mid-points), so a vertex on a grid face carries the whole point load of a traction there.
/// NOT non-negative: the vertex functions have a lobe down to -1/8 at s = 3/4 (and 1/4 from the other
/// side). With the updated schemes a particle crossing such a lobe can get a negative share of a nodal
/// mass, so the function is only offered with the total-Lagrangian scheme (`tlmpm_only`), where the
/// particles stay at fixed reference positions and the weights act as quadrature weights of a finite
/// element. The row-sum nodal masses m_I = sum_p phi_I(X_p) m_p stay positive for the usual fillings
/// (1 particle per cell = 2 per element at s = 1/4, 3/4: vertex 1/8 and mid 3/4 of the element mass,
/// per element; 2 per cell: 5/32 and 11/16; the exact integrals are 1/6 and 2/3).
/// C-infinity inside an element, only C0 across element boundaries.
/// Support: the 3 nodes of the particle's element (base = its left vertex, even); slab_cells = 2 as for
/// Bernstein (slabs coincide with elements).

#include <algorithm>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm {

struct LagrangeQuadratic {
  static constexpr const char* name = "lagrange_quadratic";
  static constexpr int support = 3;
  static constexpr int slab_cells = 2;  // one element; slabs start at node 0, so they align with elements
  /// Nodes a slab [sT, (s+1)T) of cells reaches on its axis: [sT - below, (s+1)T - 1 + above] (halo of a
  /// distributed run, tile_halo.hpp; test ShapeFunctionProperties.SlabThickness).
  static constexpr int slab_reach_below = 0, slab_reach_above = 1;
  static constexpr int min_cells = 2;          // one element
  static constexpr int cell_multiple = 2;      // every axis needs an even number of cells
  static constexpr bool tlmpm_only = true;     // negative lobes: only at fixed reference positions
  static constexpr Real min_weight = -0.125;   ///< the vertex lobe at |r| = 3/4 (other functions: 0)
  static constexpr int reproduced_degree = 2;  ///< reproduces quadratics (other functions: linears)

  /// `nodes` must be odd (an even number of cells). A particle on an element vertex belongs to the
  /// element above it (the last vertex to the last element).
  static inline void evaluate(Real xi, int nodes, int& base, Real* w, Real* dw) {
    const int elements = (nodes - 1) / 2;
    base = 2 * std::clamp(static_cast<int>(std::floor(xi / 2)), 0, elements - 1);
    const Real s = (xi - base) / 2;
    w[0] = (1 - s) * (1 - 2 * s);
    w[1] = 4 * s * (1 - s);
    w[2] = s * (2 * s - 1);
    // d/dxi = (1/2) d/ds.
    dw[0] = 2 * s - Real(1.5);
    dw[1] = 2 - 4 * s;
    dw[2] = 2 * s - Real(0.5);
  }
};

}  // namespace mpm
