// The particle count estimate (geometry/particle_count.hpp) that scenes are checked against the machine's memory
// with: exact when the sample covers the lattice, within 1-2% of the fill and of the analytic volume / sub-cell
// volume otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mpm/body_shape/primitive_shapes.hpp"
#include "mpm/geometry/particle_count.hpp"
#include "mpm/geometry/shape_filler.hpp"

using namespace mpm;
using namespace mpm::geometry;

namespace {

ShapeDescription disk_shape(double x, double y, double r) { return make_shape("disk", BallShape{{x, y, 0}, r}); }

GridGeometry<2> unit_square_grid(int cells) {
  return GridGeometry<2>(Vec<2>::Zero(), Vec<2>::Constant(1.0 / cells), {cells, cells});
}

TEST(ParticleCount, ExactWhenTheSampleCoversTheLattice) {
  const auto region = make_region<2>(disk_shape(0.5, 0.5, 0.3));
  const auto grid = unit_square_grid(10);
  const std::array<int, 3> ppc{2, 2, 1};
  const auto count = count_particles<2>(*region, grid, ppc);
  EXPECT_TRUE(count.exact);
  EXPECT_EQ(count.count, static_cast<double>(fill_region<2>(*region, grid, ppc).positions.size()));
  EXPECT_EQ(count.lattice, 12.0 * 12.0);  // the sub-cell centres 0.225 ... 0.775 of each axis (bounds 0.2, 0.8)
}

TEST(ParticleCount, SampledCountIsWithinAPercentOfTheFill) {
  // 600 x 600 lattice points in the disk's box at 100 per cell: 360,000 > 32,768, so sampled.
  const auto region = make_region<2>(disk_shape(0.5, 0.5, 0.3));
  const auto grid = unit_square_grid(10);
  const std::array<int, 3> ppc{100, 100, 1};
  const auto count = count_particles<2>(*region, grid, ppc);
  EXPECT_FALSE(count.exact);
  EXPECT_LE(count.sampled, 32768u);
  const double filled = static_cast<double>(fill_region<2>(*region, grid, ppc).positions.size());
  EXPECT_NEAR(count.count / filled, 1.0, 0.01) << count.count << " vs " << filled;
  const double analytic = std::numbers::pi * 0.09 / (1e-3 * 1e-3);  // pi r^2 / sub-cell area = 282,743
  EXPECT_NEAR(filled / analytic, 1.0, 0.001);
}

TEST(ParticleCount, TaylorAnvilAtAHundredPerCellWithoutFillingIt) {
  // examples/05_taylor_anvil at 100 per cell per axis: pi r^2 L / (h/100)^3 = 9.218e9 particles, which the fill
  // would take hours and ~2 TB to make; the sample says so in milliseconds.
  CylinderShape rod;
  rod.radius = 3.8e-3;
  rod.axis.length = 25.4e-3;
  rod.axis.axis = 2;
  const auto region = make_region<3>(make_shape("cylinder", rod));
  const GridGeometry<3> grid(Vec<3>(-0.008, -0.008, 0), Vec<3>::Constant(0.0005), {32, 32, 52});
  const auto count = count_particles<3>(*region, grid, {100, 100, 100});
  const double analytic = std::numbers::pi * 3.8e-3 * 3.8e-3 * 25.4e-3 / std::pow(5e-6, 3);
  EXPECT_NEAR(analytic, 9.218e9, 1e6);
  EXPECT_NEAR(count.count / analytic, 1.0, 0.02) << count.count;
  EXPECT_LE(count.sampled, 32768u);
}

TEST(ParticleCount, LatticeOfABoxInClosedForm) {
  const auto grid = unit_square_grid(10);
  Box<2> box{Vec<2>(0.1, 0.2), Vec<2>(0.4, 0.3)};  // 0.3 x 0.1 m at 4 per cell: 12 x 4 sub-cell centres
  EXPECT_EQ(lattice_points_in<2>(box, grid, {4, 4, 1}), 48.0);
  Box<2> thin{Vec<2>(0.1, 0.2), Vec<2>(0.4, 0.2)};  // no thickness: no sub-cell centre inside
  EXPECT_EQ(lattice_points_in<2>(thin, grid, {4, 4, 1}), 0.0);
}

}  // namespace
