// Quadratic B-spline (boundary-modified, n+1 nodes) and quadratic Bernstein shape functions: printed
// values; the derivation of the quadratic boundary functions from the open-knot Cox-de Boor basis (eqs
// 3.15-3.16); the Bernstein per-node formulas (eqs 3.24-3.25). Their properties (partition of unity,
// reproduction, non-negativity, derivatives, slab thickness) are checked with every listed function in
// test_shape_function_properties.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "mpm/shape/bernstein_quadratic.hpp"
#include "mpm/shape/quadratic_bspline.hpp"

namespace mpm {
namespace {

/// Weight and derivative of node `node` at xi (zero when the node is outside the particle's stencil).
template <class Shape>
void weight_of(Real xi, int nodes, int node, Real& w, Real& dw) {
  int base = -1;
  Real ws[Shape::support], ds[Shape::support];
  Shape::evaluate(xi, nodes, base, ws, ds);
  const int k = node - base;
  w = dw = 0;
  if (k >= 0 && k < Shape::support) {
    w = ws[k];
    dw = ds[k];
  }
}

// Interior values of the uniform quadratic B-spline at r = 0, +-1/2, +-1, +-3/2 (and beyond).
TEST(ShapeFunctionsMore, QuadraticBSplineInteriorValues) {
  const int nodes = 21, node = 10;
  const Real r[] = {0, 0.5, 1, 1.5, 2};
  const Real value[] = {0.75, 0.5, 0.125, 0, 0};
  const Real slope[] = {0, -1, -0.5, 0, 0};  // d/dr for r >= 0; odd in r
  for (int i = 0; i < 5; ++i)
    for (const Real sign : {1.0, -1.0}) {
      Real w, dw;
      weight_of<QuadraticBSpline>(node + sign * r[i], nodes, node, w, dw);
      EXPECT_NEAR(w, value[i], 1e-15) << "r = " << sign * r[i];
      EXPECT_NEAR(dw, sign * slope[i], 1e-15) << "r = " << sign * r[i];
    }
}

// Boundary types: hats in the half cell next to a face, interpolatory at the face, C1 at r = 1/2, and
// the upper face the mirror image of the lower one.
TEST(ShapeFunctionsMore, QuadraticBSplineBoundaryValues) {
  const int nodes = 9, last = nodes - 1;
  Real w, dw;
  // At the face only the face node is non-zero.
  for (int node = 0; node < nodes; ++node) {
    weight_of<QuadraticBSpline>(0, nodes, node, w, dw);
    EXPECT_EQ(w, node == 0 ? 1 : 0);
    weight_of<QuadraticBSpline>(last, nodes, node, w, dw);
    EXPECT_EQ(w, node == last ? 1 : 0);
  }
  // xi = 1/4: hats.
  const Real expect_w[] = {0.75, 0.25, 0}, expect_dw[] = {-1, 1, 0};
  for (int node = 0; node < 3; ++node) {
    weight_of<QuadraticBSpline>(0.25, nodes, node, w, dw);
    EXPECT_NEAR(w, expect_w[node], 1e-15);
    EXPECT_NEAR(dw, expect_dw[node], 1e-15);
  }
  // xi = 1: the face node is B(1) = 1/8, node 1 is B(0) = 3/4.
  weight_of<QuadraticBSpline>(1, nodes, 0, w, dw);
  EXPECT_NEAR(w, 0.125, 1e-15);
  EXPECT_NEAR(dw, -0.5, 1e-15);
  weight_of<QuadraticBSpline>(1, nodes, 1, w, dw);
  EXPECT_NEAR(w, 0.75, 1e-15);
  EXPECT_NEAR(dw, 0, 1e-15);
  // C1 across xi = 1/2 (where the boundary branch meets B) and xi = n - 1/2.
  for (const Real knot : {0.5, last - 0.5})
    for (int node = 0; node < nodes; ++node) {
      Real wl, dl, wr, dr;
      weight_of<QuadraticBSpline>(knot - 1e-12, nodes, node, wl, dl);
      weight_of<QuadraticBSpline>(knot + 1e-12, nodes, node, wr, dr);
      EXPECT_NEAR(wl, wr, 1e-11) << "node " << node << " at " << knot;
      EXPECT_NEAR(dl, dr, 1e-11) << "node " << node << " at " << knot;
    }
  // Mirror symmetry: phi_I(xi) = phi_{n-I}(n - xi), dphi_I(xi) = -dphi_{n-I}(n - xi).
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(0, last);
  for (int trial = 0; trial < 200; ++trial) {
    const Real xi = u(rng);
    for (int node = 0; node < nodes; ++node) {
      Real wm, dm;
      weight_of<QuadraticBSpline>(xi, nodes, node, w, dw);
      weight_of<QuadraticBSpline>(last - xi, nodes, last - node, wm, dm);
      EXPECT_NEAR(w, wm, 1e-14);
      EXPECT_NEAR(dw, -dm, 1e-14);
    }
  }
}

/// Cox-de Boor (eqs 3.15-3.16) with 0/0 := 0; the last knot span is closed on the right.
Real cox_de_boor(const std::vector<Real>& t, int i, int k, Real x) {
  if (k == 0) {
    if (t[i] <= x && x < t[i + 1]) return 1;
    return x == t.back() && t[i] < x && x <= t[i + 1] ? 1 : 0;
  }
  Real v = 0;
  if (t[i + k] > t[i]) v += (x - t[i]) / (t[i + k] - t[i]) * cox_de_boor(t, i, k - 1, x);
  if (t[i + k + 1] > t[i + 1]) v += (t[i + k + 1] - x) / (t[i + k + 1] - t[i + 1]) * cox_de_boor(t, i + 1, k - 1, x);
  return v;
}

// The header's derivation: open knots at the cell centres give n+3 functions N_0..N_{n+2}; merging
// N_1 (and N_{n+1}) 3/4 : 1/4 into the face node and its neighbour gives the n+1 node functions.
TEST(ShapeFunctionsMore, QuadraticBSplineFromOpenKnotBasis) {
  for (const int n : {2, 3, 4, 7}) {
    std::vector<Real> t = {0, 0, 0};
    for (int c = 0; c < n; ++c) t.push_back(c + 0.5);
    t.insert(t.end(), {Real(n), Real(n), Real(n)});
    for (int j = 0; j <= 400; ++j) {
      const Real x = n * j / Real(400);
      std::vector<Real> N(n + 3), phi(n + 1, 0);
      for (int i = 0; i < n + 3; ++i) N[i] = cox_de_boor(t, i, 2, x);
      for (int I = 1; I <= n - 1; ++I) phi[I] = N[I + 1];
      phi[0] = N[0] + 0.75 * N[1];
      phi[1] += 0.25 * N[1];
      phi[n] = N[n + 2] + 0.75 * N[n + 1];
      phi[n - 1] += 0.25 * N[n + 1];
      for (int I = 0; I <= n; ++I) {
        Real w, dw;
        weight_of<QuadraticBSpline>(x, n + 1, I, w, dw);
        ASSERT_NEAR(w, phi[I], 1e-14) << "n = " << n << ", x = " << x << ", node " << I;
      }
    }
  }
}

// Bernstein: Kronecker property at the element vertices, 1/2 and 1/4 at the element centre.
TEST(ShapeFunctionsMore, BernsteinValues) {
  const int cells = 8, nodes = cells + 1;
  Real w, dw;
  for (int vertex = 0; vertex <= cells; vertex += 2)
    for (int node = 0; node < nodes; ++node) {
      weight_of<BernsteinQuadratic>(vertex, nodes, node, w, dw);
      EXPECT_EQ(w, node == vertex ? 1 : 0) << "vertex " << vertex << ", node " << node;
    }
  for (int mid = 1; mid < cells; mid += 2)
    for (int node = 0; node < nodes; ++node) {
      weight_of<BernsteinQuadratic>(mid, nodes, node, w, dw);
      const Real expect = node == mid ? 0.5 : (std::abs(node - mid) == 1 ? 0.25 : 0);
      EXPECT_EQ(w, expect) << "mid-point " << mid << ", node " << node;
      // At the centre the mid node peaks; the vertices have slopes -+1/2 per grid spacing.
      EXPECT_NEAR(dw, node == mid - 1 ? -0.5 : (node == mid + 1 ? 0.5 : 0), 1e-15);
    }
}

// Bernstein against the review's per-node formulas (eqs 3.24-3.25, r = (x - x_I)/E with E = 2h) and
// non-negativity, at random points.
TEST(ShapeFunctionsMore, BernsteinPerNodeFormulas) {
  const int cells = 10, nodes = cells + 1;
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(0, cells);
  for (int trial = 0; trial < 1000; ++trial) {
    const Real xi = u(rng);
    for (int node = 0; node < nodes; ++node) {
      Real w, dw;
      weight_of<BernsteinQuadratic>(xi, nodes, node, w, dw);
      const Real r = (xi - node) / 2, a = std::abs(r);
      Real expect = 0;
      if (node % 2 == 0 && a <= 1) expect = (1 - a) * (1 - a);  // vertex, eq. 3.24
      if (node % 2 == 1 && a <= 0.5) expect = 0.5 - 2 * r * r;  // mid node, eq. 3.25
      EXPECT_NEAR(w, expect, 1e-14) << "xi = " << xi << ", node " << node;
      EXPECT_GE(w, 0);
    }
  }
}

}  // namespace
}  // namespace mpm
