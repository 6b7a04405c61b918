// Slope stability by strength reduction (issue 52: "Griffiths & Lane 1999, factor of safety 1.4 against Bishop's
// 1.38: within 5%"): their example 1 (set-up and criterion in tests/verification/strength_reduction.hpp), 0.5 m cells
// (20 per slope height, 3,520 particles), linear hats. The step limit is 4 times the steps the slope takes to settle
// at F = 1 (4,393 measured). Measured (docs/verification-notes.md, "Slope stability by strength reduction";
// bench/strength_reduction.py): at 20 cells per H, F = 1.35 settles after 6,801 steps (1.55 N(1)), 1.375 after 8,274
// (1.88 N(1)), 1.40 after 39,864 (9.1 N(1)), 1.425 does not within 10 N(1): the factor of safety in (1.375, 1.40) with
// this limit, (1.40, 1.425) with 10 N(1); at 40 and 80 cells per H it is (1.35, 1.375) with both limits.
// Asserted: the slope stands at F = 1.35 and does not at 1.425 (the bracket that holds at 20, 40 and 80 cells per H),
// the factor of safety within 3.6% of Griffiths & Lane's 1.4 (Bishop & Morgenstern's 1.38 inside; the issue asks for
// 5%); and the largest displacement of the stage jumps where the slope fails (3.2 mm at F = 1.35, 12.4 mm at the
// limit at 1.425). Label slow: about 30 s of CPU (28,766 steps of 3,520 particles).
#include <gtest/gtest.h>

#include "strength_reduction.hpp"

namespace mpm::strength_reduction_slow_test {  // named: a unity build puts the slow tests in one unit

using namespace verification::strength_reduction;

TEST(StrengthReduction, GriffithsLaneSlopeFailsBetweenFactors135And1425) {
  const double h = 0.5;
  const GravityStageReport unreduced = settle_slope(1.0, h, 200000);
  ASSERT_TRUE(unreduced.converged);
  const long long limit = 4 * static_cast<long long>(unreduced.steps);
  const GravityStageReport below = settle_slope(1.35, h, limit);
  const GravityStageReport above = settle_slope(1.425, h, limit);
  EXPECT_TRUE(below.converged);   // the slope stands at F = 1.4 x 0.964
  EXPECT_FALSE(above.converged);  // and not at F = 1.4 x 1.018
  EXPECT_GT(above.largest_displacement, 2 * below.largest_displacement);
}

}  // namespace mpm::strength_reduction_slow_test
