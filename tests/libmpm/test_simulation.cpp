// Determinism across thread counts, the stability guard, and the time-step control (eq. 2.73).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "mpm/scene/scene_error.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

std::string block_scene(const std::string& solver) {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.025, boundary: {y_min: fixed}}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
         "bodies:\n"
         "  - {material: m, shape: {type: box, min: [0.2, 0.0], max: [0.8, 0.5]}, particles_per_cell: 2,\n"
         "     velocity: [\"0.2*sin(5*y)\", \"-0.1*x\"]}\n"
         "solver: {" +
         solver + "}\n";
}

template <int Dim>
std::vector<double> state(const Simulation<Dim>& sim) {
  std::vector<double> s;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) {
      for (int d = 0; d < Dim; ++d) s.push_back(b.particles.x[i][d]), s.push_back(b.particles.v[i][d]);
      for (double c : b.particles.stress[i].c) s.push_back(c);
      s.push_back(b.particles.id[i]);
    }
  return s;
}

std::vector<double> run_with_threads(int threads, const std::string& solver) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  auto sim = test::simulation_from_yaml<2>(block_scene(solver));
  for (int s = 0; s < 120; ++s) sim->advance(sim->next_time_step());
  return state(*sim);
}

// Tile-coloured scatter in a fixed order (tile_binning.hpp): the same bits for any thread count.
TEST(Simulation, BitIdenticalAcrossThreadCounts) {
  for (const std::string solver : {"scheme: musl, cfl: 0.5, end_time: 1, sort_interval: 7",
                                   "scheme: usl, shape_function: cubic_bspline, cfl: 0.5, end_time: 1",
                                   "scheme: usf, cfl: 0.5, end_time: 1", "scheme: tlmpm, cfl: 0.5, end_time: 1"}) {
    const auto one = run_with_threads(1, solver);
    const auto two = run_with_threads(2, solver);
    ASSERT_EQ(one.size(), two.size());
    for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << solver << " entry " << i;
  }
}

TEST(Simulation, CflTimeStepFollowsEq273) {
  auto sim = test::simulation_from_yaml<2>(block_scene("cfl: 0.5, end_time: 1"));
  // c = sqrt((lambda + 2 mu)/rho) for E = 1e5, nu = 0.3, rho = 1000; max |v_x| = 0.2 sin(2.5) ...
  const Real E = 1e5, nu = 0.3, rho = 1000;
  const Real c = std::sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho);
  Real vx = 0, vy = 0;
  for (const auto& b : sim->bodies())
    for (Index i = 0; i < b.particles.size(); ++i) {
      vx = std::max(vx, std::abs(b.particles.v[i][0]));
      vy = std::max(vy, std::abs(b.particles.v[i][1]));
    }
  EXPECT_NEAR(sim->stable_time_step(), 0.025 / (c + std::max(vx, vy)), 1e-12);
  EXPECT_NEAR(sim->next_time_step(), 0.5 * 0.025 / (c + std::max(vx, vy)), 1e-12);
}

TEST(Simulation, FixedTimeStepAboveStableBoundIsRefused) {
  try {
    test::simulation_from_yaml<2>(block_scene("dt: 0.01, end_time: 1"), "block.yaml");
    FAIL() << "expected SceneError";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("block.yaml:"), std::string::npos) << what;
    EXPECT_NE(what.find("solver.dt"), std::string::npos) << what;
    EXPECT_NE(what.find("stable time step 0.002"), std::string::npos) << what;  // 0.025/(c + |v|) = 0.00231
  }
}

// A time step far above the bound makes the solution explode; the guard must stop it, name the step,
// body, particle and field, and leave the simulation at the last good state: the state a run that
// stopped one step earlier has, bit for bit.
TEST(Simulation, StabilityGuardStopsAndRollsBack) {
  auto sim = test::simulation_from_yaml<2>(block_scene("cfl: 0.5, end_time: 1, snapshot_interval: 4"));
  auto reference = test::simulation_from_yaml<2>(block_scene("cfl: 0.5, end_time: 1, snapshot_interval: 4"));
  const Real dt = 12 * sim->stable_time_step();
  Index failed_step = -1;
  try {
    for (int s = 0; s < 200; ++s) sim->advance(dt);
    FAIL() << "the guard never tripped";
  } catch (const StabilityError& e) {
    failed_step = e.report().step;
    const std::string what = e.what();
    EXPECT_NE(what.find("step " + std::to_string(failed_step)), std::string::npos) << what;
    EXPECT_NE(what.find("body 'body0'"), std::string::npos) << what;
    EXPECT_NE(what.find("particle "), std::string::npos) << what;
    EXPECT_FALSE(e.report().field.empty());
    EXPECT_GE(e.report().particle, 0);
  }
  ASSERT_GT(failed_step, 1);
  EXPECT_EQ(sim->step(), failed_step - 1);
  for (Index s = 1; s < failed_step; ++s) reference->advance(dt);
  const auto a = state(*sim), b = state(*reference);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(std::isfinite(a[i]));
    ASSERT_EQ(a[i], b[i]) << "entry " << i;
  }
}

TEST(Simulation, GuardCatchesParticleLeavingTheGrid) {
  const std::string scene =
      "dimension: 1\n"
      "grid: {origin: [0], extent: [1], cell_size: 0.1}\n"
      "materials: {m: {model: linear_elastic, density: 1, youngs_modulus: 1, poisson_ratio: 0}}\n"
      "bodies: [{name: rod, material: m, shape: {type: box, min: [0.6], max: [0.9]}, velocity: [5]}]\n"
      "solver: {cfl: 0.5, end_time: 1}\n";
  auto sim = test::simulation_from_yaml<1>(scene);
  try {
    sim->run();
    FAIL() << "expected StabilityError";
  } catch (const StabilityError& e) {
    EXPECT_EQ(e.report().field, "position");
    EXPECT_EQ(e.report().body, "rod");
    EXPECT_NE(std::string(e.what()).find("left the grid box through x_max"), std::string::npos) << e.what();
    EXPECT_EQ(e.report().face, "x_max");
  }
  for (const auto& b : sim->bodies())
    for (Index i = 0; i < b.particles.size(); ++i) EXPECT_LE(b.particles.x[i][0], 1.0);
}

}  // namespace
}  // namespace mpm

#include "mpm/output/output_writer.hpp"

namespace mpm {
namespace {

// A module that only subscribes to the phase between the grid-to-particle transfer and the stress
// update: it forces the unfused path, which must give exactly the same numbers as the fused one.
struct CountingModule final : Module<2> {
  int calls = 0;
  std::string_view name() const override { return "counting"; }
  unsigned phases() const override { return phase_after_g2p; }
  void after_g2p(StepContext<2>&) override { ++calls; }
};

TEST(Simulation, ModuleBetweenTransferAndStressGivesSameResults) {
  for (const std::string solver : {"scheme: musl, cfl: 0.5, end_time: 1", "scheme: usl, cfl: 0.5, end_time: 1",
                                   "scheme: usf, cfl: 0.5, end_time: 1", "scheme: tlmpm, cfl: 0.5, end_time: 1"}) {
    auto fused = test::simulation_from_yaml<2>(block_scene(solver));
    auto split = test::simulation_from_yaml<2>(block_scene(solver));
    auto module = std::make_shared<CountingModule>();
    split->add_module(module);
    for (int s = 0; s < 30; ++s) {
      fused->advance(fused->next_time_step());
      split->advance(split->next_time_step());
    }
    EXPECT_EQ(module->calls, 30);
    const auto a = state(*fused), b = state(*split);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << solver << " entry " << i;
  }
}

// velocity_gradient is written only when asked. A linear velocity field v = (0.1 x, -0.05 y) maps exactly
// onto nodes whose support is filled with particles on both sides (2 PPC, symmetric), so inside the body
// L = diag(0.1, -0.05) after the first step (zero stress: no force). FLIP keeps the particle velocities
// exactly linear; with PIC the bias of the half-filled edge nodes (eq. 2.43 reproduces only constant
// fields there) would be carried two cells inwards by the double mapping.
TEST(Simulation, VelocityGradientOutputOnDemand) {
  const std::string scene =
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.1}\n"
      "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
      "bodies: [{material: m, shape: {type: box, min: [0.2, 0.2], max: [0.8, 0.8]}, velocity: [\"0.1*x\", "
      "\"-0.05*y\"]}]\n"
      "solver: {scheme: musl, flip_fraction: 1, dt: 1.0e-6, end_time: 1}\n"
      "output: {fields: [velocity_gradient]}\n";
  auto sim = test::simulation_from_yaml<2>(scene);
  EXPECT_TRUE(sim->bodies()[0].particles.has_field("velocity_gradient"));
  sim->advance(1e-6);
  OutputWriter<2> writer(std::filesystem::temp_directory_path() / "mpm_vg_test", "p", {"velocity_gradient"}, false, 0);
  const io::PointCloud cloud = writer.particle_cloud(*sim);
  std::filesystem::remove_all(writer.directory());
  const auto& L = cloud.fields.at(0);
  ASSERT_EQ(L.name, "velocity_gradient");
  int interior = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const double x = cloud.points[3 * i], y = cloud.points[3 * i + 1];
    if (x < 0.3 || x > 0.7 || y < 0.3 || y > 0.7) continue;  // the edge cells touch half-filled nodes
    ++interior;
    EXPECT_NEAR(L.values[9 * i + 0], 0.1, 1e-9);
    EXPECT_NEAR(L.values[9 * i + 4], -0.05, 1e-9);
    EXPECT_NEAR(L.values[9 * i + 1], 0, 1e-9);
  }
  EXPECT_GT(interior, 50);
  // Without the output field nothing is stored.
  auto plain = test::simulation_from_yaml<2>(block_scene("cfl: 0.5, end_time: 1"));
  EXPECT_FALSE(plain->bodies()[0].particles.has_field("velocity_gradient"));
}

}  // namespace
}  // namespace mpm

namespace mpm {
namespace {

std::string floor_scene(const std::string& floor) {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [2, 1], cell_size: 0.05, boundary: {y_min: " +
         floor +
         "}}\n"
         "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}\n"
         "bodies: [{material: m, shape: {type: box, min: [0.2, 0.0], max: [0.6, 0.2]}, velocity: [0.5, 0]}]\n"
         "solver: {scheme: musl, cfl: 0.4, end_time: 0.3, gravity: [0, -9.81]}\n";
}

// A block sliding on the floor under gravity: a slip floor fixes only the normal velocity, so the
// horizontal momentum is untouched (frictionless) and the block does not sink; a fixed floor also
// stops the tangential velocity of the bottom nodes, which brakes the block.
TEST(Simulation, SlipAndFixedFloors) {
  auto slip = test::simulation_from_yaml<2>(floor_scene("slip"));
  auto fixed = test::simulation_from_yaml<2>(floor_scene("fixed"));
  const Real p0 = slip->energy().momentum[0];
  slip->run();
  fixed->run();
  EXPECT_NEAR(slip->energy().momentum[0], p0, 1e-9 * p0);
  EXPECT_LT(fixed->energy().momentum[0], 0.9 * p0);
  Real lowest = 1;
  for (Index i = 0; i < slip->bodies()[0].particles.size(); ++i)
    lowest = std::min(lowest, slip->bodies()[0].particles.x[i][1]);
  EXPECT_GT(lowest, 0.0);
}

// A prescribed face velocity is an expression of t, applied at t for v^t and at t + dt for the updated
// and re-mapped velocities.
TEST(Simulation, PrescribedFaceVelocityFollowsExpressionOfTime) {
  const std::string scene =
      "dimension: 1\n"
      "grid: {origin: [0], extent: [1], cell_size: 0.1, boundary: {x_min: fixed, x_max: {velocity: [\"0.02*t\"]}}}\n"
      "materials: {m: {model: linear_elastic, density: 1, youngs_modulus: 1, poisson_ratio: 0}}\n"
      "bodies: [{material: m, shape: {type: box, min: [0], max: [1]}}]\n"
      "solver: {scheme: musl, dt: 0.01, end_time: 1}\n";
  auto sim = test::simulation_from_yaml<1>(scene);
  for (int s = 0; s < 10; ++s) sim->advance(0.01);
  const auto& v = sim->grid().velocity;
  EXPECT_DOUBLE_EQ(v.back().mapped[0], 0.02 * sim->time());  // re-mapped v^{t+dt}, t + dt = now
  EXPECT_DOUBLE_EQ(v.back().updated[0], 0.02 * sim->time());
  EXPECT_EQ(v.front().mapped[0], 0.0);
  // The bar is pulled: its last particle moves towards +x.
  EXPECT_GT(sim->bodies()[0].particles.v.back()[0], 0.0);
}

}  // namespace
}  // namespace mpm

namespace mpm {
namespace {

// A prescribed face traction (review §4.2.2) is an external force: with nothing else acting, the
// body's momentum grows as traction x face area x time, whatever the scheme.
TEST(Simulation, FaceTractionGivesNewtonsSecondLaw) {
  for (const std::string scheme : {"tlmpm", "musl", "usl", "usf"}) {
    const std::string bar =
        "dimension: 1\n"
        "grid: {origin: [0], extent: [1], cell_size: 0.05, boundary: {x_max: {traction: [\"-2000\"]}}}\n"
        "materials: {m: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
        "bodies: [{material: m, shape: {type: box, min: [0], max: [1]}}]\n"
        "solver: {scheme: " +
        scheme + ", cfl: 0.5, end_time: 0.01}\n";
    auto sim = test::simulation_from_yaml<1>(bar);
    sim->run();
    EXPECT_NEAR(sim->energy().momentum[0], -2000 * sim->time(), 1e-9 * 2000 * sim->time()) << scheme;
  }
  // 2D: a traction in y on the top face of a block filling the grid: force = traction x width (1.5 m).
  const std::string block =
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [1.5, 1], cell_size: 0.1, boundary: {y_max: {traction: [0, \"100*t\"]}}}\n"
      "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
      "bodies: [{material: m, shape: {type: box, min: [0, 0], max: [1.5, 1]}}]\n"
      "solver: {scheme: tlmpm, dt: 1.0e-4, end_time: 0.05}\n";
  auto sim = test::simulation_from_yaml<2>(block);
  sim->run();
  // Explicit in time: the force at the start of each step, sum_n 100 n dt * 1.5 * dt = 150 dt^2 N(N-1)/2.
  const Real dt = 1e-4, n = std::round(sim->time() / dt);
  EXPECT_NEAR(sim->energy().momentum[1], 150 * dt * dt * n * (n - 1) / 2, 1e-9);
  EXPECT_NEAR(sim->energy().momentum[0], 0, 1e-12);
}

}  // namespace
}  // namespace mpm

namespace mpm {
namespace {

// domain_size output: l_p(0) = h/ppc, stretched by F_11 with cpGIMP (eq. 3.14), fixed with uGIMP.
TEST(Simulation, DomainSizeOutputFollowsF) {
  for (const std::string shape : {"cpgimp", "gimp"}) {
    const std::string bar =
        "dimension: 1\n"
        "grid: {origin: [0], extent: [2], cell_size: 0.1}\n"
        "materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e3, poisson_ratio: 0}}\n"
        "bodies: [{material: m, shape: {type: box, min: [0.5], max: [1.0]}, velocity: [\"0.2*(x-0.75)\"]}]\n"
        "solver: {shape_function: " +
        shape +
        ", cfl: 0.5, end_time: 0.05}\n"
        "output: {fields: [domain_size, deformation_gradient]}\n";
    auto sim = test::simulation_from_yaml<1>(bar);
    sim->run();
    OutputWriter<1> writer(std::filesystem::temp_directory_path() / "mpm_domain_test", "p",
                           {"domain_size", "deformation_gradient"}, false, 0);
    const io::PointCloud cloud = writer.particle_cloud(*sim);
    std::filesystem::remove_all(writer.directory());
    const auto& size = cloud.fields.at(0).values;
    const auto& F = cloud.fields.at(1).values;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const double expected = 0.05 * (shape == "cpgimp" ? F[9 * i] : 1.0);  // h / 2 particles per cell
      ASSERT_NEAR(size[3 * i], expected, 1e-15) << shape;
      ASSERT_EQ(size[3 * i + 1], 0.0);
    }
  }
}

}  // namespace
}  // namespace mpm
