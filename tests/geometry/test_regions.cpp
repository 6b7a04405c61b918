// Regions without files (geometry/region.hpp): polygons (with holes), cylinders along any direction and
// union / intersection / difference, filled on the lattice and compared with analytic areas and volumes.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/body_shape/primitive_shapes.hpp"
#include "mpm/geometry/polygon_region.hpp"
#include "mpm/geometry/shape_filler.hpp"

using namespace mpm;
using namespace mpm::geometry;

namespace {

ShapeDescription polygon(std::vector<std::array<double, 2>> corners) {
  return make_shape("polygon", PolygonShape{std::move(corners)});
}

ShapeDescription disk(double x, double y, double r) { return make_shape("disk", BallShape{{x, y, 0}, r}); }

ShapeDescription box(std::array<double, 3> lo, std::array<double, 3> hi) { return make_shape("box", BoxShape{lo, hi}); }

ShapeDescription combine(const std::string& type, std::vector<ShapeDescription> parts) {
  return make_shape(type, CombinedShape{std::move(parts)});
}

const GridGeometry<2> unit_grid(Vec<2>::Zero(), Vec<2>::Constant(0.01), {100, 100});

double area(const ParticleSeeds<2>& s) { return s.volume * static_cast<double>(s.positions.size()); }

}  // namespace

// An L-shaped hexagon whose corners lie on sub-cell boundaries: the lattice count is exact and the
// volumes sum to the shoelace area 0.6 x 0.6 - 0.3 x 0.3 = 0.27 m^2.
TEST(Regions, PolygonFillIsExactOnTheLattice) {
  const auto s = polygon({{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.5}, {0.5, 0.5}, {0.5, 0.8}, {0.2, 0.8}});
  const auto seeds = fill_shape<2>(s, unit_grid, {2, 2, 1}, nullptr);
  EXPECT_EQ(seeds.positions.size(), 10800u);  // 0.27 m^2 / (0.005 m)^2
  EXPECT_NEAR(area(seeds), 0.27, 1e-14);
  for (const auto& x : seeds.positions) EXPECT_FALSE(x[0] > 0.5 && x[1] > 0.5);
  // Either orientation.
  auto reversed = s.as<PolygonShape>().vertices;
  std::reverse(reversed.begin(), reversed.end());
  EXPECT_EQ(fill_shape<2>(polygon(reversed), unit_grid, {2, 2, 1}, nullptr).positions, seeds.positions);
}

// Two loops, even-odd: a square with a square hole.
TEST(Regions, PolygonLoopsMakeHoles) {
  const PolygonRegion square_with_hole(
      {{{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}}, {{0.3, 0.3}, {0.3, 0.7}, {0.7, 0.7}, {0.7, 0.3}}});
  EXPECT_NEAR(*square_with_hole.exact_volume(), 0.64 - 0.16, 1e-15);
  EXPECT_TRUE(square_with_hole.contains(Vec<2>(0.2, 0.5)));
  EXPECT_FALSE(square_with_hole.contains(Vec<2>(0.5, 0.5)));
  EXPECT_FALSE(square_with_hole.contains(Vec<2>(0.95, 0.5)));
}

// Union, intersection and difference of a box and a disk, against the analytic areas (disk area of the
// lattice within 1% at 40 sub-cells per radius).
TEST(Regions, BooleanCombinations) {
  const auto b = box({0.2, 0.2, 0}, {0.6, 0.8, 0});  // 0.24 m^2
  const auto d = disk(0.6, 0.5, 0.2);                // half inside the box: pi 0.04 / 2 overlap
  const double disk_area = M_PI * 0.04, overlap = disk_area / 2;
  const struct {
    std::string type;
    double expected;
  } cases[] = {{"union", 0.24 + disk_area - overlap}, {"intersection", overlap}, {"difference", 0.24 - overlap}};
  for (const auto& c : cases) {
    const auto seeds = fill_shape<2>(combine(c.type, {b, d}), unit_grid, {2, 2, 1}, nullptr);
    EXPECT_NEAR(area(seeds) / c.expected, 1, 0.01) << c.type;
  }
  // The difference leaves no particle inside the disk; the intersection none outside the box.
  for (const auto& x : fill_shape<2>(combine("difference", {b, d}), unit_grid, {2, 2, 1}, nullptr).positions)
    EXPECT_GT((x - Vec<2>(0.6, 0.5)).norm(), 0.2);
  for (const auto& x : fill_shape<2>(combine("intersection", {b, d}), unit_grid, {2, 2, 1}, nullptr).positions)
    EXPECT_LE(x[0], 0.6);
}

// A cylinder along (1, 1, 1)/sqrt(3): particles satisfy the analytic test, the lattice volume is within
// 2% of pi r^2 L, and the bounding box holds every particle.
TEST(Regions, CylinderAlongAnyDirection) {
  CylinderShape cylinder;
  cylinder.center = {0.25, 0.25, 0.25};
  cylinder.radius = 0.1;
  cylinder.axis.length = 0.8;
  cylinder.axis.axis = -1;
  const double a = 1 / std::sqrt(3.0);
  cylinder.axis.direction = {a, a, a};
  ShapeDescription s = make_shape("cylinder", cylinder);
  const GridGeometry<3> g(Vec<3>::Zero(), Vec<3>::Constant(0.02), {50, 50, 50});
  const auto seeds = fill_shape<3>(s, g, {2, 2, 2}, nullptr);
  const Vec<3> base(0.25, 0.25, 0.25), axis = Vec<3>::Constant(a);
  for (const auto& x : seeds.positions) {
    const double t = (x - base).dot(axis);
    ASSERT_GE(t, 0);
    ASSERT_LE(t, 0.8);
    ASSERT_LE((x - base - t * axis).norm(), 0.1 + 1e-12);
  }
  const double volume = seeds.volume * static_cast<double>(seeds.positions.size());
  EXPECT_NEAR(volume / (M_PI * 0.01 * 0.8), 1, 0.02);
  const auto region = make_region<3>(s);
  const Box<3> bounds = region->bounds();
  // End disks reach r sqrt(1 - 1/3) beyond the axis end points on every axis.
  EXPECT_NEAR(bounds.lo[0], 0.25 - 0.1 * std::sqrt(2.0 / 3), 1e-15);
  EXPECT_NEAR(bounds.hi[2], 0.25 + 0.8 * a + 0.1 * std::sqrt(2.0 / 3), 1e-15);
  // Axis-aligned cylinders are unchanged: axis index wins over the direction.
  cylinder.axis.axis = 0;
  s = make_shape("cylinder", cylinder);
  EXPECT_TRUE(make_region<3>(s)->contains(Vec<3>(0.9, 0.25, 0.25)));
}
