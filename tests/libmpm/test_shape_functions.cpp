// Values of the cubic B-spline and GIMP functions against the review's formulas: the boundary-modified cubic
// (eqs 3.18-3.20), uGIMP in the paper's piecewise form (eqs 3.12-3.13) and cpGIMP's domain (eq. 3.14).
// The properties every function has (partition of unity, reproduction, slabs, derivatives) are checked for
// every listed function in test_shape_function_properties.cpp.
#include <gtest/gtest.h>

#include <random>

#include "mpm/shape/cubic_bspline.hpp"
#include "mpm/shape/stencil.hpp"

namespace mpm {
namespace {

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

}  // namespace
}  // namespace mpm
