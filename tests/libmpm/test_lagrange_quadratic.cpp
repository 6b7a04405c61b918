// Quadratic Lagrange (finite-element) shape function of the 000 paper (Nuttall 2025, eq. 28 with three
// equally spaced abscissae) on elements of two grid cells: the Kronecker property at every node, the element
// formulas and the negative lobe (-1/8), the 3D stencil gradient against finite differences, positive
// row-sum nodal masses for the particle fillings the verification uses, and the registration (tlmpm only,
// even cell counts). Partition of unity, linear and quadratic reproduction, the lobe bound, 1D derivatives
// and the slab thickness are checked with every listed function in test_shape_function_properties.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "mpm/schemes/scheme.hpp"
#include "mpm/shape/lagrange_quadratic.hpp"
#include "mpm/shape/stencil.hpp"

namespace mpm {
namespace {

using Shape = LagrangeQuadratic;

/// Weight and derivative (per grid spacing) of `node` at xi (grid units), 0 outside the support.
void weight_of(Real xi, int nodes, int node, Real& w, Real& dw) {
  int base = 0;
  Real ws[Shape::support], ds[Shape::support];
  Shape::evaluate(xi, nodes, base, ws, ds);
  w = dw = 0;
  if (node >= base && node < base + Shape::support) {
    w = ws[node - base];
    dw = ds[node - base];
  }
}

// Kronecker delta at every node: vertices (even) and mid-points (odd), the grid faces included.
TEST(LagrangeQuadratic, KroneckerAtNodes) {
  const int cells = 8, nodes = cells + 1;
  for (int at = 0; at < nodes; ++at)
    for (int node = 0; node < nodes; ++node) {
      Real w, dw;
      weight_of(at, nodes, node, w, dw);
      EXPECT_EQ(w, node == at ? 1 : 0) << "at node " << at << ", weight of node " << node;
    }
  // In 2D: the weight of node (i, j) at node (k, l) is delta_ik delta_jl.
  const GridGeometry<2> g(Vec<2>(0.5, -1), Vec<2>(0.2, 0.1), {4, 6});
  Stencil<2, Shape> st;
  for (Index n = 0; n < g.node_count(); ++n) {
    st.compute(VecU<2>(g.node_position(g.node_indices(n))), g);
    for (int a = 0; a < st.count; ++a) EXPECT_NEAR(st.w[a], st.node[a] == n ? 1 : 0, 1e-13);  // xi from x
  }
}

// The element functions of eq. 28 (s = (x - a)/E, E = 2h): (1-s)(1-2s), 4s(1-s), s(2s-1); per node,
// r = (x - x_I)/E: vertex (1-|r|)(1-2|r|) on |r| <= 1, mid node 1 - 4r^2 on |r| <= 1/2. The vertex
// function's lobe is -1/8 at |r| = 3/4.
TEST(LagrangeQuadratic, ElementFormulas) {
  const int cells = 10, nodes = cells + 1;
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(0, cells);
  for (int trial = 0; trial < 1000; ++trial) {
    const Real xi = u(rng);
    for (int node = 0; node < nodes; ++node) {
      Real w, dw;
      weight_of(xi, nodes, node, w, dw);
      const Real r = (xi - node) / 2, a = std::abs(r);
      Real expect = 0;
      if (node % 2 == 0 && a <= 1) expect = (1 - a) * (1 - 2 * a);
      if (node % 2 == 1 && a <= 0.5) expect = 1 - 4 * r * r;
      EXPECT_NEAR(w, expect, 1e-14) << "xi = " << xi << ", node " << node;
    }
  }
  Real w, dw;
  weight_of(4 + 1.5, nodes, 4, w, dw);  // vertex 4, three quarters of its right element
  EXPECT_NEAR(w, -0.125, 1e-15);
  EXPECT_NEAR(dw, 0, 1e-15);  // the minimum of the lobe
  weight_of(4 - 1.5, nodes, 4, w, dw);
  EXPECT_NEAR(w, -0.125, 1e-15);
}

// The Stencil's physical gradient in 3D against finite differences of its weights (the 1D derivatives are
// checked with every listed function in test_shape_function_properties.cpp).
TEST(LagrangeQuadratic, StencilGradientAgainstFiniteDifferences) {
  const GridGeometry<3> g(Vec<3>(-0.2, 0.1, 0), Vec<3>(0.1, 0.15, 0.2), {4, 6, 2});
  Stencil<3, Shape> st, sp, sm;
  const VecU<3> x(0.033, 0.41, 0.27);  // inside elements on every axis
  st.compute(x, g);
  for (int d = 0; d < 3; ++d) {
    VecU<3> xp = x, xm = x;
    xp[d] += 1e-7;
    xm[d] -= 1e-7;
    sp.compute(xp, g);
    sm.compute(xm, g);
    for (int a = 0; a < st.count; ++a) {
      ASSERT_EQ(sp.node[a], st.node[a]);
      EXPECT_NEAR(st.grad[a][d], (sp.w[a] - sm.w[a]) / 2e-7, 1e-6) << "axis " << d << ", node " << st.node[a];
    }
  }
}

// Row-sum nodal masses sum_p phi_I(X_p) m_p of an element filled at the sub-cell centres: 1 per cell (the
// 000 paper's 2 per element at s = 1/4, 3/4) gives vertex 1/8, mid 3/4 of the element mass; 2 per cell
// gives 5/32 and 11/16; n per cell tends to the exact integrals 1/6 and 2/3 as 1/n^2. All positive.
TEST(LagrangeQuadratic, RowSumNodalMassesArePositive) {
  for (const int per_cell : {1, 2, 3, 4, 8}) {
    const int cells = 2, nodes = 3, count = per_cell * cells;
    Real mass[3] = {0, 0, 0};
    for (int k = 0; k < count; ++k) {
      const Real xi = (k + 0.5) / per_cell;
      for (int node = 0; node < nodes; ++node) {
        Real w, dw;
        weight_of(xi, nodes, node, w, dw);
        mass[node] += w / count;
      }
    }
    EXPECT_GT(mass[0], 0) << per_cell;
    EXPECT_GT(mass[1], 0) << per_cell;
    EXPECT_NEAR(mass[0], mass[2], 1e-15);
    EXPECT_NEAR(mass[0] + mass[1] + mass[2], 1, 1e-14);
    if (per_cell == 1) {
      EXPECT_NEAR(mass[0], 0.125, 1e-15);
      EXPECT_NEAR(mass[1], 0.75, 1e-15);
    }
    if (per_cell == 2) {
      EXPECT_NEAR(mass[0], 5.0 / 32, 1e-15);
      EXPECT_NEAR(mass[1], 11.0 / 16, 1e-15);
    }
    // Midpoint rule on 2n sub-intervals of a quadratic with second derivative 4: error 4/(24 (2n)^2).
    EXPECT_NEAR(mass[0], 1.0 / 6 - 1.0 / (24 * per_cell * per_cell), 1e-14);
  }
}

TEST(LagrangeQuadratic, RegisteredForTlmpmOnly) {
  const ShapeFunctionInfo* info = find_shape_function("lagrange_quadratic");
  ASSERT_NE(info, nullptr);
  EXPECT_TRUE(info->tlmpm_only);
  EXPECT_TRUE(info->even_cells);
  EXPECT_EQ(info->min_cells, 2);
  EXPECT_FALSE(info->particle_domain);
  for (const char* other : {"linear", "bernstein", "cubic_bspline"})
    EXPECT_FALSE(find_shape_function(other)->tlmpm_only);
  const auto names = shape_function_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "lagrange_quadratic"), names.end());
  const auto tl = make_scheme<2>("tlmpm", "lagrange_quadratic");
  EXPECT_EQ(tl->shape_function(), "lagrange_quadratic");
  EXPECT_EQ(tl->slab_cells(), 2);
  for (const char* scheme : {"usl", "musl", "usf"}) {
    EXPECT_THROW(make_scheme<1>(scheme, "lagrange_quadratic"), std::invalid_argument) << scheme;
  }
}

}  // namespace
}  // namespace mpm
