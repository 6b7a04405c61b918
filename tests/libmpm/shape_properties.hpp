#pragma once
// Property check shared by the shape-function tests (review §3.1): partition of unity, gradients
// summing to zero, linear reproduction (sum phi_I x_I = x, sum x_I (x) grad phi_I = I) and non-negative
// weights, at random points of an anisotropic grid, a share of them in the cells next to the faces, on
// nodes and half-cells, and exactly on both corners of the box.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "mpm/shape/stencil.hpp"

namespace mpm::test {

/// Axis d gets cells + step*d cells (step 2 keeps the count even for Bernstein).
template <int Dim, class Shape>
void check_properties(int cells, int step = 1) {
  Vec<Dim> origin, h;
  std::array<int, Dim> n{};
  for (int d = 0; d < Dim; ++d) {
    origin[d] = -0.3 * (d + 1);
    h[d] = 0.1 + 0.05 * d;
    n[d] = cells + step * d;
  }
  const GridGeometry<Dim> g(origin, h, n);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(0, 1);
  Stencil<Dim, Shape> st;
  for (int trial = 0; trial < 3000; ++trial) {
    VecU<Dim> x;
    for (int d = 0; d < Dim; ++d) {
      Real xi = u(rng) * n[d];
      if (trial % 5 == 1) xi = u(rng);                  // first cell
      if (trial % 5 == 2) xi = n[d] - u(rng);           // last cell
      if (trial % 5 == 3) xi = 2 * u(rng);              // first two cells
      if (trial % 5 == 4) xi = std::floor(xi * 2) / 2;  // nodes and half-cells, faces included
      x[d] = origin[d] + xi * h[d];
    }
    if (trial == 0) x = VecU<Dim>(origin);
    if (trial == 5) x = VecU<Dim>(g.upper());
    st.compute(x, g);
    Real sum_w = 0;
    Vec<Dim> sum_grad = Vec<Dim>::Zero(), reproduced = Vec<Dim>::Zero();
    Mat<Dim> grad_x = Mat<Dim>::Zero();
    for (int a = 0; a < st.count; ++a) {
      ASSERT_GE(st.w[a], -1e-14) << "weights must be non-negative";
      ASSERT_GE(st.node[a], 0);
      ASSERT_LT(st.node[a], g.node_count());
      const Vec<Dim> xI = g.node_position(g.node_indices(st.node[a]));
      Vec<Dim> grad;
      for (int d = 0; d < Dim; ++d) grad[d] = st.grad[a][d];
      sum_w += st.w[a];
      sum_grad += grad;
      reproduced += st.w[a] * xI;
      grad_x += xI * grad.transpose();
    }
    ASSERT_NEAR(sum_w, 1, 1e-13);
    ASSERT_LT(sum_grad.norm(), 1e-11);
    ASSERT_LT((reproduced - Vec<Dim>(x)).norm(), 1e-12);
    ASSERT_LT((grad_x - Mat<Dim>::Identity()).norm(), 1e-11);
  }
}

/// The scatter writes every node of a particle's stencil (zero weights included). Slabs of
/// `Shape::slab_cells` cells along the axis, binned as bin_by_slab does; two slabs of the same colour
/// (s and s+2) must not reach a common node.
template <class Shape>
void check_slab_thickness(int cells) {
  const int nodes = cells + 1, slabs = (cells + Shape::slab_cells - 1) / Shape::slab_cells;
  std::vector<int> lo(slabs, nodes), hi(slabs, -1);
  auto visit = [&](Real xi) {
    const int slab = std::clamp(static_cast<int>(xi), 0, cells - 1) / Shape::slab_cells;
    int base = -1;
    Real w[Shape::support], dw[Shape::support];
    Shape::evaluate(xi, nodes, base, w, dw);
    lo[slab] = std::min(lo[slab], base);
    hi[slab] = std::max(hi[slab], base + Shape::support - 1);
  };
  std::mt19937 rng(9);
  std::uniform_real_distribution<Real> u(0, cells);
  for (int i = 0; i < 4000; ++i) visit(u(rng));
  for (int i = 0; i <= 4 * cells; ++i) visit(i / Real(4));  // cell faces, centres and quarters exactly
  for (int s = 0; s + 2 < slabs; ++s)
    EXPECT_LT(hi[s], lo[s + 2]) << Shape::name << ": slabs " << s << " and " << s + 2 << " share a node";
}

}  // namespace mpm::test
