// Shape-function properties every MPM weighting family must have (review §3.1): partition of unity,
// gradients summing to zero, and linear reproduction (sum phi_I x_I = x, sum x_I (x) grad phi_I = I),
// checked in 1D, 2D and 3D at random points including the cells next to the grid faces, where the
// cubic B-spline uses its boundary-modified functions (review eqs 3.18-3.21).
#include <gtest/gtest.h>

#include <random>

#include "mpm/shape/cubic_bspline.hpp"
#include "mpm/shape/factored_stencil.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "mpm/shape/quadratic_bspline.hpp"
#include "mpm/shape/stencil.hpp"
#include "shape_properties.hpp"

namespace mpm {
namespace {

using test::check_properties;

TEST(ShapeFunctions, LinearHat1D) { check_properties<1, LinearHat>(7); }
TEST(ShapeFunctions, LinearHat2D) { check_properties<2, LinearHat>(5); }
TEST(ShapeFunctions, LinearHat3D) { check_properties<3, LinearHat>(4); }
TEST(ShapeFunctions, CubicBSpline1D) { check_properties<1, CubicBSpline>(7); }
TEST(ShapeFunctions, CubicBSpline2D) { check_properties<2, CubicBSpline>(6); }
TEST(ShapeFunctions, CubicBSpline3D) { check_properties<3, CubicBSpline>(5); }
TEST(ShapeFunctions, CubicBSplineMinimumGrid) { check_properties<1, CubicBSpline>(4); }
TEST(ShapeFunctions, QuadraticBSpline2DFaces) { check_properties<2, QuadraticBSpline>(6); }
TEST(ShapeFunctions, QuadraticBSpline3DFaces) { check_properties<3, QuadraticBSpline>(4); }

// Values printed in the review for the boundary-modified cubic (eqs 3.18-3.20), at a particle half a
// cell from the lower face: type 1 at r = 0.5, type 2 at r = -0.5, type 3 at r = -1.5.
TEST(ShapeFunctions, CubicBSplineBoundaryValues) {
  int base = -1;
  Real w[4], dw[4];
  CubicBSpline::evaluate(0.5, 10, base, w, dw);
  EXPECT_EQ(base, 0);
  EXPECT_NEAR(w[0], 0.125 / 6 - 0.5 + 1, 1e-15);
  EXPECT_NEAR(w[1], 0.125 / 3 - 0.25 + 2.0 / 3, 1e-15);
  EXPECT_NEAR(w[2], 0.125 / 6, 1e-15);
  EXPECT_NEAR(w[3], 0, 1e-15);
  // Interpolatory at the face: only the face node is non-zero there.
  CubicBSpline::evaluate(0.0, 10, base, w, dw);
  EXPECT_NEAR(w[0], 1, 1e-15);
  EXPECT_NEAR(w[1] + w[2] + w[3], 0, 1e-15);
}

}  // namespace
}  // namespace mpm

#include "mpm/shape/gimp.hpp"

namespace mpm {
namespace {

// uGIMP in the paper's piecewise form (eq. 3.12-3.13), h = 1, particle length l = 2a <= 1.
void paper_ugimp(Real x, Real l, Real& w, Real& dw) {
  const Real ax = std::abs(x), s = x < 0 ? -1 : 1;
  if (ax < l / 2) {
    w = 1 - (4 * x * x + l * l) / (4 * l);
    dw = -2 * x / l;
  } else if (ax <= 1 - l / 2) {
    w = 1 - ax;
    dw = -s;
  } else if (ax < 1 + l / 2) {
    w = (1 + l / 2 - ax) * (1 + l / 2 - ax) / (2 * l);
    dw = -s * (1 + l / 2 - ax) / l;
  } else {
    w = dw = 0;
  }
}

TEST(ShapeFunctions, GimpMatchesPaperFormulaAndFiniteDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(0, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    const Real xi = 3 + 4 * u(rng), a = 0.05 + 0.95 * u(rng);  // half-length up to one cell
    int base;
    Real w[4], dw[4];
    gimp_detail::evaluate(xi, 12, a, base, w, dw);
    for (int k = 0; k < 4; ++k) {
      const Real r = xi - (base + k);
      if (a <= 0.5) {
        Real wp, dwp;
        paper_ugimp(r, 2 * a, wp, dwp);
        ASSERT_NEAR(w[k], wp, 1e-14) << "r " << r << " a " << a;
        ASSERT_NEAR(dw[k], dwp, 1e-13);
      }
      const Real e = 1e-6;
      int b2;
      Real wp[4], wm[4], d2[4];
      gimp_detail::evaluate(xi + e, 12, a, b2, wp, d2);
      if (b2 != base) continue;
      gimp_detail::evaluate(xi - e, 12, a, b2, wm, d2);
      if (b2 != base) continue;
      ASSERT_NEAR(dw[k], (wp[k] - wm[k]) / (2 * e), 1e-7);
    }
  }
}

// PU, zero gradient sum and linear reproduction hold wherever the domain lies inside the grid
// (no ghost nodes), for any domain up to two cells long, in 2D and 3D.
template <int Dim>
void check_gimp(int cells) {
  Vec<Dim> origin = Vec<Dim>::Zero(), h;
  std::array<int, Dim> n{};
  for (int d = 0; d < Dim; ++d) h[d] = 0.1 * (d + 1), n[d] = cells;
  const GridGeometry<Dim> g(origin, h, n);
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(0, 1);
  Stencil<Dim, CpGimp> st;
  for (int trial = 0; trial < 2000; ++trial) {
    VecU<Dim> x;
    Vec<Dim> half;
    for (int d = 0; d < Dim; ++d) {
      const Real a = 0.05 + 0.95 * u(rng);  // cells
      half[d] = a * h[d];
      x[d] = (a + (cells - 2 * a) * u(rng)) * h[d];  // domain inside the box
    }
    st.compute(x, g, half);
    Real sum = 0;
    Vec<Dim> grad_sum = Vec<Dim>::Zero(), reproduced = Vec<Dim>::Zero();
    Mat<Dim> grad_x = Mat<Dim>::Zero();
    for (int a = 0; a < st.count; ++a) {
      ASSERT_GE(st.w[a], -1e-15);
      const Vec<Dim> xI = g.node_position(g.node_indices(st.node[a]));
      Vec<Dim> grad;
      for (int d = 0; d < Dim; ++d) grad[d] = st.grad[a][d];
      sum += st.w[a];
      grad_sum += grad;
      reproduced += st.w[a] * xI;
      grad_x += xI * grad.transpose();
    }
    ASSERT_NEAR(sum, 1, 1e-13);
    ASSERT_LT(grad_sum.norm(), 1e-11);
    ASSERT_LT((reproduced - Vec<Dim>(x)).norm(), 1e-12);
    ASSERT_LT((grad_x - Mat<Dim>::Identity()).norm(), 1e-11);
  }
}

TEST(ShapeFunctions, Gimp1D) { check_gimp<1>(6); }
TEST(ShapeFunctions, Gimp2D) { check_gimp<2>(5); }
TEST(ShapeFunctions, Gimp3D) { check_gimp<3>(4); }

// cpGIMP stretches the domain with the diagonal of F (eq. 3.14); uGIMP keeps it.
TEST(ShapeFunctions, CpGimpDomainFollowsF) {
  ParticleSet<2> p;
  p.add(Vec<2>(0.5, 0.5), 1, 0.01);
  p.add_field<VecU<2>>("domain_half_length0", VecU<2>(0.05, 0.05));
  p.F[0] << 1.5, 0.3, 0.1, 0.8;
  const ParticleDomain<2, CpGimp> cp(p);
  const ParticleDomain<2, UGimp> u(p);
  EXPECT_NEAR(cp(0)[0], 0.075, 1e-15);
  EXPECT_NEAR(cp(0)[1], 0.04, 1e-15);
  EXPECT_NEAR(u(0)[0], 0.05, 1e-15);
}

// The factored stencil TLMPM caches (factored_stencil.hpp) visits the same nodes, in the same order, with
// the same weights and gradients as the full stencil, at random points including the boundary cells.
template <int Dim, class Shape>
void check_factored_matches_full(int cells, Real half_cells = 0) {
  std::array<int, Dim> n;
  n.fill(cells);
  const GridGeometry<Dim> g(Vec<Dim>::Constant(-0.3), Vec<Dim>::Constant(0.25), n);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    VecU<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = g.origin[d] + u(rng) * g.h[d] * cells;
    const Vec<Dim> half = Vec<Dim>::Constant(half_cells * 0.25);
    Stencil<Dim, Shape> full;
    FactoredStencil<Dim, Shape> factored;
    full.compute(x, g, half);
    factored.compute(x, g, half);
    int a = 0;
    factored.for_each(g, [&](Index node, Real w, const Vec<Dim>& grad) {
      ASSERT_LT(a, full.count);
      EXPECT_EQ(node, full.node[a]);
      EXPECT_NEAR(w, full.w[a], 1e-15);
      for (int d = 0; d < Dim; ++d) EXPECT_NEAR(grad[d], full.grad[a][d], 1e-13);
      ++a;
    });
    EXPECT_EQ(a, full.count);
  }
}

TEST(ShapeFunctions, FactoredStencilMatchesFull) {
  check_factored_matches_full<1, LinearHat>(6);
  check_factored_matches_full<2, LinearHat>(5);
  check_factored_matches_full<3, LinearHat>(4);
  check_factored_matches_full<2, CubicBSpline>(6);
  check_factored_matches_full<3, CubicBSpline>(5);
  check_factored_matches_full<3, QuadraticBSpline>(4);
  check_factored_matches_full<2, UGimp>(5, 0.5);
  check_factored_matches_full<3, UGimp>(4, 0.5);
}

}  // namespace
}  // namespace mpm
