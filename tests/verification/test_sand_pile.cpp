// Angle of repose of a cohesionless sand pile in plane strain (issue 52, item 4), the quick version at 10 cells per
// pile width: the set-up, the measurement and the references are those of sand_pile.hpp (docs/theory.md eqs.
// 18.25-18.26: the static slope limit is phi for Mohr-Coulomb and asin(eta) = 24.24 and 32.99 deg for the
// plane_strain Drucker-Prager cone without dilation at phi = 25 and 35 deg). The 20-cell case with the 2-degree target
// of the issue is the slow test tests/slow/test_sand_pile_20_cells.cpp.
//
// At 10 cells per width the flank stands 1.9 to 2.7 deg steeper than the limit (measured, bench/sand_pile.py and
// docs/verification-notes.md, "Angle of repose of a sand pile"): the quadratic B-splines spread a shear band over about
// three cells, so the shallow slide that bounds a cohesionless slope cannot form in a flank 10 cells deep and a deeper,
// stronger mechanism holds it. Hence a bound of 3 deg here, and 2 deg only in the 20-cell test. The second check makes
// the test fail when the angle does not follow phi: the two piles' angles differ by at least half of the 10 deg
// between their friction angles.
#include <gtest/gtest.h>

#include "sand_pile.hpp"

namespace mpm::sand_pile_quick_test {  // named: the unity build puts the verification tests in one unit

using namespace verification::sand_pile;

TEST(SandPile, FlankAngleFollowsTheFrictionAngleAtTenCellsPerWidth) {
  for (const std::string model : {"mohr_coulomb", "drucker_prager"}) {
    const PileResult loose = run_pile({.model = model, .phi = 25, .cells = 10, .damping = 0.95, .time = 40});
    const PileResult dense = run_pile({.model = model, .phi = 35, .cells = 10, .damping = 0.95, .time = 40});
    for (const PileResult& r : {loose, dense}) {
      EXPECT_GE(r.flank.points, 6) << model;                  // a flank of 6 cells or more to fit a line to
      EXPECT_NEAR(r.flank.angle, r.limit, 3.0) << model;      // the coarse grid's over-steepening, see above
      EXPECT_LT(r.speed, 1e-3 * std::sqrt(g * H0)) << model;  // at rest
    }
    EXPECT_GT(dense.flank.angle - loose.flank.angle, 5.0) << model;  // the angle follows phi
  }
}

}  // namespace mpm::sand_pile_quick_test
