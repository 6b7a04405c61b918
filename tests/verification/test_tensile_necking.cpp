// Tensile test to failure (review §6.3.2, Weldox 460E) at a coarse resolution, pulled ten times faster than
// in the review to fit the test suite (still quasi-static: the ramp lasts ~80 wave transits of the bar).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tensile_necking.hpp"

namespace mpm {
namespace {

// Considere: the engineering stress of a rate-independent Johnson-Cook bar peaks where
// B n eps^(n-1) = A + B eps^n; for Weldox 460E (A = 499 MPa, B = 382 MPa, n = 0.458) eps = 0.0945, so the
// ultimate engineering stress is (A + B eps^n) exp(-eps) = 572 MPa at an engineering strain exp(eps) - 1 =
// 0.099 (uniform elongation; elastic strain 0.003 neglected).
TEST(TensileNecking, CoarseNeckAtMidLengthAndFailure) {
  TensileSpec s;
  s.h = 1e-3;
  s.v_max = 10;
  s.tau = 0.1e-3;
  s.record_interval = 20;
  const TensileResult r = run_tensile_necking(s);
  std::printf(
      "[ measured ] h = 1 mm: %lld particles, %lld steps, %.1f s; peak %.1f MPa at strain %.4f; neck at "
      "z = %.2f mm, radius %.3f mm, damage there %.3f; largest damage at z = %.2f mm; stress below 10%% of "
      "the peak at strain %.4f\n",
      r.particles, r.steps, r.wall_seconds, r.peak_stress / 1e6, r.strain_at_peak, r.neck_z * 1e3, r.neck_radius * 1e3,
      r.neck_max_damage, r.max_damage_z * 1e3, r.failure_strain);
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  const double A = 499e6, B = 382e6, n = 0.458;
  double lo = 0.01, hi = 0.5;  // Considere strain by bisection
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (B * n * std::pow(mid, n - 1) - A - B * std::pow(mid, n) > 0 ? lo : hi) = mid;
  }
  const double eps = 0.5 * (lo + hi), uts = (A + B * std::pow(eps, n)) * std::exp(-eps);
  EXPECT_NEAR(uts, 572e6, 1e6);
  // Measured: 571.9 MPa at 0.085 (the recorded curve is flat at its peak: the strain there is loose).
  EXPECT_NEAR(r.peak_stress, uts, 0.02 * uts);
  EXPECT_NEAR(r.strain_at_peak, std::exp(eps) - 1, 0.025);
  // The neck forms at mid-length (measured: the slice at 14.5 mm, its twin at 15.5 mm equal by symmetry),
  // damage reaches 1 there first, and the bar breaks (measured: stress < 10% of the peak at strain 0.348).
  EXPECT_NEAR(r.neck_z, 15e-3, 1e-3);
  EXPECT_LT(r.neck_radius, 0.6 * 3e-3);
  EXPECT_EQ(r.neck_max_damage, 1.0);
  EXPECT_NEAR(r.max_damage_z, 15e-3, 1.5e-3);
  EXPECT_GT(r.failure_strain, 0.25);
  EXPECT_LT(r.failure_strain, 0.45);
}

}  // namespace
}  // namespace mpm
