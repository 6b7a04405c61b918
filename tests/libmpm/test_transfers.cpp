// Conservation by the transfers (review eqs 2.41, 2.48): P2G conserves mass and momentum exactly
// (partition of unity); a full USL or MUSL step with no external force conserves linear momentum.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/boundary/velocity_face.hpp"
#include "mpm/schemes/transfer_kernels.hpp"
#include "mpm/shape/cubic_bspline.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

template <int Dim, class Shape>
void check_p2g_conservation() {
  Vec<Dim> origin = Vec<Dim>::Zero(), h = Vec<Dim>::Constant(0.1);
  std::array<int, Dim> cells;
  cells.fill(8);
  Grid<Dim> grid(GridGeometry<Dim>(origin, h, cells));
  Body<Dim> body;
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(0, 0.8), m(0.5, 2);
  Real mass = 0;
  Vec<Dim> momentum = Vec<Dim>::Zero();
  for (int i = 0; i < 500; ++i) {
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = u(rng);
    body.particles.add(x, m(rng), 1e-3);
    for (int d = 0; d < Dim; ++d) body.particles.v.back()[d] = m(rng) - 1.25;
    mass += body.particles.mass.back();
    momentum += body.particles.mass.back() * body.particles.v.back();
  }
  bin_by_tile(body.particles, grid.geometry, Shape::slab_cells, body.bins);
  kernels::reset_grid(grid);
  kernels::particles_to_grid<Dim, Shape>(body, grid);
  Real grid_mass = 0;
  Vec<Dim> grid_momentum = Vec<Dim>::Zero();
  for (const auto& n : grid.node) {
    grid_mass += n.mass;
    grid_momentum += n.momentum;
  }
  EXPECT_NEAR(grid_mass, mass, 1e-12 * mass);
  EXPECT_LT((grid_momentum - momentum).norm(), 1e-12 * mass);
}

TEST(Transfers, P2GConservesMassAndMomentumLinear1D) { check_p2g_conservation<1, LinearHat>(); }
TEST(Transfers, P2GConservesMassAndMomentumLinear2D) { check_p2g_conservation<2, LinearHat>(); }
TEST(Transfers, P2GConservesMassAndMomentumLinear3D) { check_p2g_conservation<3, LinearHat>(); }
TEST(Transfers, P2GConservesMassAndMomentumCubic2D) { check_p2g_conservation<2, CubicBSpline>(); }
TEST(Transfers, P2GConservesMassAndMomentumCubic3D) { check_p2g_conservation<3, CubicBSpline>(); }

// A free elastic disk with a non-uniform initial velocity, no gravity and no boundary condition:
// internal forces sum to zero, so linear momentum stays at its initial value through many steps.
// USL with hat functions is run at a tenth of the velocity: with the strong shear it suffers the
// small-mass instability of eq. 2.62 (hat gradients do not vanish with the weight at the body's edge)
// and the guard stops it near step 80, which is the known USL behaviour, not a conservation issue.
std::string free_disk(const std::string& scheme, const std::string& shape, double flip, double amplitude = 1) {
  const std::string a = std::to_string(amplitude);
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
         "materials: {m: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
         "bodies:\n"
         "  - {material: m, shape: {type: disk, center: [0.5, 0.5], radius: 0.25}, particles_per_cell: 2,\n"
         "     velocity: [\"" +
         a + "*0.3*sin(6*y)\", \"" + a +
         "*(0.2*cos(5*x)+0.1)\"]}\n"
         "solver: {scheme: " +
         scheme + ", shape_function: " + shape + ", flip_fraction: " + std::to_string(flip) +
         ", cfl: 0.4, end_time: 0.1}\n";
}

void check_momentum(const std::string& scheme, const std::string& shape, double flip, double amplitude = 1) {
  auto sim = test::simulation_from_yaml<2>(free_disk(scheme, shape, flip, amplitude));
  const EnergyBalance e0 = sim->energy();
  for (int s = 0; s < 200; ++s) sim->advance(sim->next_time_step());
  const EnergyBalance e1 = sim->energy();
  EXPECT_NEAR(e1.mass, e0.mass, 1e-12 * e0.mass);
  EXPECT_LT((e1.momentum - e0.momentum).norm(), 1e-11 * e0.mass) << scheme << " " << shape;
}

TEST(Transfers, UslConservesMomentum) { check_momentum("usl", "linear", 1.0, 0.1); }
TEST(Transfers, MuslConservesMomentum) { check_momentum("musl", "linear", 1.0); }
TEST(Transfers, MuslPicBlendConservesMomentum) { check_momentum("musl", "linear", 0.5); }
TEST(Transfers, MuslCubicConservesMomentum) { check_momentum("musl", "cubic_bspline", 1.0); }
TEST(Transfers, UslCubicConservesMomentum) { check_momentum("usl", "cubic_bspline", 0.9); }
TEST(Transfers, UsfConservesMomentum) { check_momentum("usf", "linear", 1.0, 0.1); }
TEST(Transfers, UsfCubicConservesMomentum) { check_momentum("usf", "cubic_bspline", 1.0); }
TEST(Transfers, TlmpmConservesMomentum) { check_momentum("tlmpm", "linear", 1.0); }
TEST(Transfers, TlmpmCubicConservesMomentum) { check_momentum("tlmpm", "cubic_bspline", 0.99); }
TEST(Transfers, MuslGimpConservesMomentum) { check_momentum("musl", "gimp", 1.0); }
TEST(Transfers, UslCpGimpConservesMomentum) { check_momentum("usl", "cpgimp", 1.0, 0.1); }
TEST(Transfers, TlmpmGimpConservesMomentum) { check_momentum("tlmpm", "gimp", 1.0); }

std::string apic_disk(const std::string& scheme) {
  std::string s = free_disk(scheme, "linear", 1.0);
  return s.replace(s.find("flip_fraction: "), std::string("flip_fraction: 1.000000").size(), "velocity_transfer: apic");
}
TEST(Transfers, MuslApicConservesMomentum) {
  auto sim = test::simulation_from_yaml<2>(apic_disk("musl"));
  const EnergyBalance e0 = sim->energy();
  for (int s = 0; s < 200; ++s) sim->advance(sim->next_time_step());
  EXPECT_LT((sim->energy().momentum - e0.momentum).norm(), 1e-11 * e0.mass);
}

}  // namespace
}  // namespace mpm

namespace mpm {
namespace {

// Walls keep particles in (boundary/grid_boundary.hpp): a face whose normal velocity is held at 0 (`fixed`,
// `slip`) bounds the positions; free faces and prescribed non-zero velocities do not; NaN stays NaN for
// the stability guard.
TEST(GridWalls, ClampOnlyAtWallFaces) {
  const GridGeometry<2> g(Vec<2>(-1, 0), Vec<2>(0.5, 0.25), {4, 8});  // [-1, 1] x [0, 2]
  std::array<VelocityFaceSpec, 4> faces{};
  faces[1].velocity[0] = "0";  // x_max slip: a wall
  faces[2].velocity[0] = "0";  // y_min: tangential only, not a wall
  faces[3].velocity[1] = "0";  // y_max: a wall ...
  faces[3].velocity[0] = "0";  // ... held in both components (fixed)
  faces[0].velocity[0] = "2";  // x_min moves at 2 m/s: a piston, not a wall
  std::vector<std::unique_ptr<FaceCondition<2>>> conditions;
  for (int f = 0; f < 4; ++f) conditions.push_back(std::make_unique<VelocityFace<2>>(g, f, faces[f]));
  const GridBoundary<2> b(g, std::move(conditions));
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(b.wall_lower(), Vec<2>(-inf, -inf));
  EXPECT_EQ(b.wall_upper(), Vec<2>(1, 2));
  VecU<2> x(1.25, -0.5);
  kernels::keep_inside_walls<2>(x, b.wall_lower(), b.wall_upper());
  EXPECT_EQ(x[0], 1.0);
  EXPECT_EQ(x[1], -0.5);  // the free y_min face: the guard reports the particle
  x = VecU<2>(std::nan(""), 3);
  kernels::keep_inside_walls<2>(x, b.wall_lower(), b.wall_upper());
  EXPECT_TRUE(std::isnan(x[0]));
  EXPECT_EQ(x[1], 2.0);
}

}  // namespace
}  // namespace mpm
