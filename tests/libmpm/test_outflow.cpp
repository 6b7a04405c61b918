/// Outflow faces (grid.boundary.FACE: outflow; mpm/boundary/grid_boundary.hpp): particles that cross the face leave
/// their body at the end of the step, and what leaves is booked per face. The books must close: remaining + outflow
/// = initial mass (exact sums, to one rounding each), and the energy balance E(t) - E(0) - W + E_out stays at the
/// round-off of a stress-free block.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mpm/core/exact_sum.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/diagnostics/energy_sentinel.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

/// A 0.4 m x 0.4 m block (2 x 2 particles per cell of 0.1 m) moving up at 1.3 m/s, without gravity, towards the
/// outflow face y_max = 1 m of a 1 m x 1 m grid: it translates without stress and leaves row by row.
std::string block_scene(const std::string& scheme, const std::string& shape, const std::string& top = "outflow") {
  return test::fill(R"(
dimension: 2
grid:
  extent: [1, 1]
  cell_size: 0.1
  boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: @TOP@}
materials:
  rubber: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
bodies:
  - name: block
    material: rubber
    shape: {type: box, min: [0.3, 0.5], max: [0.7, 0.9]}
    particles_per_cell: 2
    velocity: [0, 1.3]
solver:
  scheme: @SCHEME@
  shape_function: @SHAPE@
  dt: 1.0e-3
  end_time: 1
)",
                    {{"SCHEME", scheme}, {"SHAPE", shape}, {"TOP", top}});
}

constexpr double block_speed = 1.3, block_dt = 1.0e-3;

/// The initial particles whose height after `steps` steps at the block's speed is beyond y = 1 m - margin.
std::vector<Index> predicted_leavers(const ParticleSet<2>& p, int steps, double margin) {
  std::vector<Index> out;
  for (Index i = 0; i < p.size(); ++i)
    if (p.x[i][1] + steps * block_dt * block_speed > 1 - margin) out.push_back(i);
  return out;
}

template <int Dim>
const EnergySentinel<Dim>* sentinel_of(const Simulation<Dim>& sim) {
  for (const auto& m : sim.modules())
    if (const auto* s = dynamic_cast<const EnergySentinel<Dim>*>(m.get())) return s;
  return nullptr;
}

/// Runs the block scene for 150 and 300 steps and checks the particle count, the books and the energy balance.
/// `margin`: the outflow face's (a particle domain must leave before it crosses the face: see BlockLeavesWith...).
void check_block(const std::string& scheme, const std::string& shape, double margin = 0) {
  SCOPED_TRACE(scheme + " " + shape);
  auto sim = test::simulation_from_yaml<2>(
      block_scene(scheme, shape, margin > 0 ? "{type: outflow, margin: " + std::to_string(margin) + "}" : "outflow"));
  const ParticleSet<2> initial = sim->bodies()[0].particles;
  const EnergyBalance e0 = sim->energy();
  for (const int steps : {150, 300}) {
    sim->run({}, steps);
    const auto leavers = predicted_leavers(initial, steps, margin);
    // the particles nearest the plane at this step are at least 0.015 m from it: no round-off doubt
    EXPECT_EQ(sim->particle_count(), initial.size() - static_cast<Index>(leavers.size())) << steps << " steps";
    ASSERT_EQ(sim->boundary().outflow().size(), 1u);
    const OutflowBook& book = sim->boundary().outflow()[0];
    EXPECT_EQ(book.face, 3);
    EXPECT_EQ(book.particle_count(), static_cast<double>(leavers.size()));
    // mass: the exact sum of the leavers' masses, and remaining + outflow = initial to one rounding of each sum
    ExactSum left;
    for (Index i : leavers) left += initial.mass[i];
    const EnergyBalance out = book.value(), now = sim->energy();
    EXPECT_EQ(out.mass, left.value());
    EXPECT_NEAR(now.mass + out.mass, e0.mass, 2e-16 * e0.mass);
    // momentum: every particle carried 1.3 m/s up (a rigid translation: round-off only)
    EXPECT_NEAR(out.momentum[1], block_speed * out.mass, 1e-12 * block_speed * out.mass);
    EXPECT_NEAR(now.momentum[1] + out.momentum[1], e0.momentum[1], 1e-12 * e0.momentum[1]);
    EXPECT_NEAR(out.kinetic, 0.5 * out.mass * block_speed * block_speed, 1e-12 * out.kinetic);
    // energy: E(t) + E_out = E(0) (no work, no dissipation in a rigid translation)
    EXPECT_NEAR(now.total() + sim->boundary().outflow_energy(), e0.total(), 1e-10 * e0.total());
  }
  // The sentinel's balance includes E_out: without it B would be -E_out, about -0.7 E(0) here, and its ratio to
  // the tolerance (1% of the energy scale) about -70.
  const auto* sentinel = sentinel_of(*sim);
  ASSERT_NE(sentinel, nullptr);
  EXPECT_LT(std::abs(sentinel->last_ratio()), 1e-6);
  // one notice, on the first step particles left: the top row (8 particles at 0.875 m) crosses 1 m at step 97,
  // 0.975 m at step 77
  const int first = margin > 0 ? 77 : 97;
  ASSERT_EQ(sim->boundary().outflow_notices().size(), 1u);
  const OutflowNotice& notice = sim->boundary().outflow_notices()[0];
  EXPECT_EQ(notice.step, first);
  EXPECT_EQ(notice.particles, 8);
  EXPECT_NE(
      notice.message().find("body block: 8 particles left through y_max (outflow) at step " + std::to_string(first)),
      std::string::npos)
      << notice.message();
}

TEST(Outflow, BlockLeavesWithClosedBooksUsl) { check_block("usl", "linear"); }
TEST(Outflow, BlockLeavesWithClosedBooksMusl) { check_block("musl", "linear"); }
TEST(Outflow, BlockLeavesWithClosedBooksUsf) { check_block("usf", "linear"); }
TEST(Outflow, BlockLeavesWithEveryShapeFunction) {
  for (const char* shape : {"quadratic_bspline", "cubic_bspline", "bernstein", "cpdi_q4", "cpdi_r4"})
    check_block("musl", shape);
  // GIMP's particle domain (half-width h / (2 ppc) = 0.025 m here) loses the weight of its part beyond the last node:
  // with margin 0 a particle slows down as its domain crosses the face (at 300 steps 40 particles were left instead
  // of 16). A margin of the domain's half-width removes it before its domain reaches the face.
  for (const char* shape : {"gimp", "cpgimp"}) check_block("musl", shape, 0.025);
}

/// `stop` (the default written out) removes nothing and keeps no books.
TEST(Outflow, BoundaryWithoutOutflowHasNoBooks) {
  auto sim = test::simulation_from_yaml<2>(block_scene("usl", "linear"));
  EXPECT_TRUE(sim->boundary().removes_particles());
  auto closed = test::simulation_from_yaml<2>(block_scene("usl", "linear", "stop"));
  EXPECT_FALSE(closed->boundary().removes_particles());
  EXPECT_TRUE(closed->boundary().outflow().empty());
}

/// A face without a condition keeps the guard's behaviour: the block stops the run when it crosses y_max.
TEST(Outflow, FaceWithoutConditionStopsTheRun) {
  auto sim = test::simulation_from_yaml<2>(block_scene("usl", "linear", "free"));
  EXPECT_THROW(sim->run({}, 300), StabilityError);
}

/// An open-top tank: a block thrown up at 6 m/s under gravity leaves through y_max; the energy that left balances
/// the books to the time discretisation's error (symplectic Euler under constant gravity: O(g v dt) per unit mass).
TEST(Outflow, OpenTankSplash) {
  auto sim = test::simulation_from_yaml<2>(R"(
dimension: 2
grid:
  extent: [1, 1]
  cell_size: 0.05
  boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: outflow}
materials:
  gel: {model: neo_hookean, density: 1000, youngs_modulus: 2.0e5, poisson_ratio: 0.3}
bodies:
  - name: gel
    material: gel
    shape: {type: box, min: [0.35, 0.1], max: [0.65, 0.4]}
    velocity: [0.5, 6]
solver:
  scheme: musl
  shape_function: cubic_bspline
  gravity: [0, -9.81]
  cfl: 0.5
  end_time: 0.14
)");
  const EnergyBalance e0 = sim->energy();
  const Index n0 = sim->particle_count();
  sim->run();
  const EnergyBalance now = sim->energy(), out = sim->boundary().outflow()[0].value();
  std::printf("[ measured ] open tank: %ld of %ld particles left; E(0) %.6g J, E(t) %.6g J, E_out %.6g J\n",
              static_cast<long>(n0 - sim->particle_count()), static_cast<long>(n0), e0.total(), now.total(),
              sim->boundary().outflow_energy());
  EXPECT_LT(sim->particle_count(), n0);
  EXPECT_GT(sim->particle_count(), 0);
  EXPECT_EQ(sim->boundary().outflow()[0].particle_count(), static_cast<double>(n0 - sim->particle_count()));
  EXPECT_NEAR(now.mass + out.mass, e0.mass, 2e-16 * e0.mass);
  EXPECT_NEAR(now.total() + sim->boundary().outflow_energy(), e0.total(), 2e-3 * e0.total());
  const auto* sentinel = sentinel_of(*sim);
  ASSERT_NE(sentinel, nullptr);
  EXPECT_FALSE(sentinel->drift());
}

/// A checkpoint after material left restarts bit for bit: the particles kept, the books and the notices.
TEST(Outflow, CheckpointAfterOutflowRestartsExactly) {
  const std::string scene = block_scene("musl", "cubic_bspline");
  auto reference = test::simulation_from_yaml<2>(scene);
  reference->run({}, 120);  // 8 rows of particles have left by step 120... or some of them: past step 97
  ASSERT_LT(reference->particle_count(), 64);
  StateArchive archive;
  reference->save_state(archive);
  reference->run({}, 200);
  auto restarted = test::simulation_from_yaml<2>(scene);
  restarted->restore_state(archive);
  EXPECT_EQ(restarted->step(), 120);
  restarted->run({}, 200);
  const auto& a = reference->bodies()[0].particles;
  const auto& b = restarted->bodies()[0].particles;
  ASSERT_EQ(a.size(), b.size());
  for (Index i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.id[i], b.id[i]);
    EXPECT_EQ(Vec<2>(a.x[i]), Vec<2>(b.x[i]));
    EXPECT_EQ(Vec<2>(a.v[i]), Vec<2>(b.v[i]));
  }
  const EnergyBalance out_a = reference->boundary().outflow()[0].value();
  const EnergyBalance out_b = restarted->boundary().outflow()[0].value();
  EXPECT_EQ(out_a.mass, out_b.mass);
  EXPECT_EQ(out_a.kinetic, out_b.kinetic);
  EXPECT_EQ(out_a.momentum, out_b.momentum);
  EXPECT_EQ(reference->boundary().outflow_notices().size(), restarted->boundary().outflow_notices().size());
}

/// 1D, 3D and axisymmetric: a bar, a cube and a ring leave through their upper face with the books closed.
TEST(Outflow, OneDimensionThreeDimensionsAndAxisymmetric) {
  {
    auto sim = test::simulation_from_yaml<1>(R"(
dimension: 1
grid: {extent: [1], cell_size: 0.1, boundary: {x_min: fixed, x_max: outflow}}
materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0}}
bodies: [{material: m, shape: {type: box, min: [0.3], max: [0.7]}, velocity: [2.3]}]
solver: {scheme: usl, dt: 1.0e-3, end_time: 0.2}
)");
    const double m0 = sim->energy().mass;
    sim->run();
    EXPECT_LT(sim->particle_count(), 8);
    EXPECT_NEAR(sim->energy().mass + sim->boundary().outflow()[0].value().mass, m0, 2e-16 * m0);
  }
  {
    auto sim = test::simulation_from_yaml<3>(R"(
dimension: 3
grid: {extent: [1, 1, 1], cell_size: 0.25, boundary: {z_min: slip, z_max: {type: outflow, margin: 0.05}}}
materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}
bodies: [{material: m, shape: {type: box, min: [0.25, 0.25, 0.25], max: [0.75, 0.75, 0.75]}, velocity: [0, 0, 2.3]}]
solver: {scheme: usf, dt: 1.0e-3, end_time: 0.15}
)");
    const double m0 = sim->energy().mass;
    const Index n0 = sim->particle_count();
    sim->run();
    EXPECT_LT(sim->particle_count(), n0);
    EXPECT_NEAR(sim->energy().mass + sim->boundary().outflow()[0].value().mass, m0, 2e-16 * m0);
  }
  {
    auto sim = test::simulation_from_yaml<2>(R"(
dimension: 2
grid: {coordinates: axisymmetric, extent: [1, 1], cell_size: 0.1, boundary: {y_min: slip, y_max: outflow}}
materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}
bodies: [{material: m, shape: {type: box, min: [0, 0.5], max: [0.4, 0.9]}, velocity: [0, 2.3]}]
solver: {scheme: musl, dt: 1.0e-3, end_time: 0.1}
)");
    const double m0 = sim->energy().mass;
    const Index n0 = sim->particle_count();
    sim->run();
    EXPECT_LT(sim->particle_count(), n0);
    EXPECT_NEAR(sim->energy().mass + sim->boundary().outflow()[0].value().mass, m0, 2e-16 * m0);
  }
}

}  // namespace
}  // namespace mpm
