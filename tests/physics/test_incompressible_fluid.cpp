// The incompressible fluid and its pressure projection (docs/theory.md §21, eqs 21.1-21.5): a column of water at
// rest, a dam break in a closed tank (no energy from anywhere), the Martin & Moyce surge front, an exact restart.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "../apps/run_mpm.hpp"
#include "../libmpm/scene_fixture.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/diagnostics/energy_sentinel.hpp"
#include "mpm/fluids/pressure_projection.hpp"
#include "mpm/shape/linear_hat.hpp"

namespace mpm {
namespace {

/// Water 0.2 m wide and 0.4 m deep filling a tank 0.5 m high with free-slip walls, 1 cm cells, 2 x 2 particles per
/// cell, for 1 s.
std::string projected_column(const std::string& solver, const std::string& tolerance = "1.0e-12") {
  return test::fill(R"yaml(dimension: 2
grid: {origin: [0, 0], extent: [0.2, 0.5], cell_size: 0.01, boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: slip}}
materials:
  water: {model: incompressible_fluid, density: 1000, viscosity: 1.0e-3, projection_tolerance: @TOLERANCE@}
bodies:
  - {name: water, material: water, shape: {type: box, min: [0, 0], max: [0.2, 0.4]}, particles_per_cell: 2}
solver: {@SOLVER@, cfl: 0.5, gravity: [0, -9.81], end_time: 1.0}
)yaml",
                    {{"SOLVER", solver}, {"TOLERANCE", tolerance}});
}

Real fastest_particle(const Simulation<2>& sim) {
  Real v = 0;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) v = std::max(v, Vec<2>(b.particles.v[i]).norm());
  return v;
}

// Hats (the cell integral, eq. 21.1a) with each explicit scheme: the projection balances gravity exactly, the
// column does not move (fastest particle after 1 s: 4.7e-12 m/s with musl), and every particle carries the
// hydrostatic pressure of its cell's centre, rho g (H - y_c), to the solver's tolerance (3925 Pa at the bottom).
TEST(IncompressibleFluid, ColumnStaysAtRestWithTheHydrostaticPressure) {
  for (const std::string scheme : {"musl", "usl", "usf"}) {
    auto sim = test::simulation_from_yaml<2>(projected_column("scheme: " + scheme + ", shape_function: linear"),
                                             "column.yaml");
    sim->run();
    EXPECT_LT(fastest_particle(*sim), 1e-10) << scheme;
    const auto& p = sim->bodies()[0].particles;
    Real worst = 0;
    for (Index i = 0; i < p.size(); ++i) {
      const Real y_c = (std::floor(p.x[i][1] / 0.01) + 0.5) * 0.01;
      const Real expected = 1000 * 9.81 * (0.4 - y_c);
      const Real pressure = -p.stress[i].full().trace() / 3;
      worst = std::max(worst, std::abs(pressure - expected));
    }
    EXPECT_LT(worst, 1e-6 * 1000 * 9.81 * 0.4) << scheme;
  }
  // With the default tolerance (1e-8) the column stays at rest to 1e-12 of its gravity potential, which the energy
  // sentinel takes for round-off (its scale's floor, 1e-9 E(0)): no drift (it warned at step 50 before the floor).
  auto sim =
      test::simulation_from_yaml<2>(projected_column("scheme: musl, shape_function: linear", "1.0e-8"), "column.yaml");
  sim->run();
  for (const auto& m : sim->modules())
    if (const auto* sentinel = dynamic_cast<const EnergySentinel<2>*>(m.get())) {
      EXPECT_FALSE(sentinel->drift().has_value()) << sentinel->largest_ratio();
    }
}

// Quadratic B-splines (the particles' quadrature, eq. 21.1b): the nodes above the surface that the particles' mass
// reaches have no cell of their own, so the column settles first (fastest particle 0.036 m/s at 0.1 s, 5e-3 m/s at
// 1 s) and stays within a particle spacing of where it started, its bottom pressure within 2% of rho g H.
TEST(IncompressibleFluid, ColumnWithBSplinesSettles) {
  auto sim = test::simulation_from_yaml<2>(
      projected_column("scheme: musl, shape_function: quadratic_bspline, velocity_transfer: apic"), "column.yaml");
  sim->run();
  EXPECT_LT(fastest_particle(*sim), 0.02);
  const auto& p = sim->bodies()[0].particles;
  Real top = 0, bottom_pressure = 0;
  for (Index i = 0; i < p.size(); ++i) {
    top = std::max(top, p.x[i][1]);
    if (p.x[i][1] < 0.01) bottom_pressure = std::max(bottom_pressure, -p.stress[i].full().trace() / 3);
  }
  EXPECT_NEAR(top, 0.3975, 0.005);
  EXPECT_NEAR(bottom_pressure, 1000 * 9.81 * 0.4, 0.02 * 1000 * 9.81 * 0.4);
}

/// The dam break of examples/14 without the obstacle: a column 0.146 m x 0.292 m in a closed square tank of 0.584 m,
/// free-slip walls, `cells` cells across the column.
std::string closed_tank(int cells, const std::string& solver) {
  return test::fill(R"yaml(dimension: 2
grid: {origin: [0, 0], extent: [0.584, 0.584], cell_size: @H@, boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: slip}}
materials:
  water: {model: incompressible_fluid, density: 1000, viscosity: 1.0e-3}
bodies:
  - {name: water, material: water, shape: {type: box, min: [0, 0], max: [0.146, 0.292]}, particles_per_cell: 2}
solver: {@SOLVER@, cfl: 0.5, gravity: [0, -9.81], end_time: 0.6}
)yaml",
                    {{"H", fmt::format("{:.17g}", 0.146 / cells)}, {"SOLVER", solver}});
}

// Issue 48's "no energy from noise": in the closed tank the total energy falls at every step, with hats and FLIP (the
// solver's defaults) and with quadratic B-splines and FLIP, through the impact on the far wall and the run-up (0.6 s).
// Quadratic B-splines with APIC blew up in this tank at 0.49 s until particles in the cells next to a wall took APIC's
// light-node rule (there the boundary B-splines are hats; transfer_kernels.hpp, affine_matrix_of_trial): the trial
// velocity of a nearly empty node grew x15 per step (the weakly compressible fluid with the same settings inverted a
// particle at 0.56 s: not the projection's).
// Measured at 20 cells: largest step-to-step change -2.0e-5 E0 (hats, to 1 s), energy at 0.6 s -18% (the impact);
// at 40 and 80 cells (bench, to 1 s) the same: never above E0.
TEST(IncompressibleFluid, ClosedTankNeverGainsEnergy) {
  for (const std::string solver :
       {"scheme: musl, shape_function: linear", "scheme: musl, shape_function: quadratic_bspline",
        "scheme: musl, shape_function: quadratic_bspline, velocity_transfer: apic"}) {
    auto sim = test::simulation_from_yaml<2>(closed_tank(20, solver), "tank.yaml");
    const Real e0 = sim->energy().total();
    Real last = e0, largest_rise = -1e300;
    sim->run([&](const Simulation<2>& s) {
      const Real e = s.energy().total();
      largest_rise = std::max(largest_rise, e - last);
      last = e;
    });
    EXPECT_LE(largest_rise, 1e-12 * e0) << solver;
    EXPECT_LT(last, 0.95 * e0) << solver;  // the impact on the far wall has happened
    EXPECT_GT(last, 0.5 * e0) << solver;
  }
}

// The surge front of Martin & Moyce (1952), a = 2.25 in, against their measurements (tests/data/
// dam_break_martin_moyce.csv): the model's front runs ahead by the gate's release (+16% at T = 1, as the weakly
// compressible example's), at the experiment's speed from T = 4 (dZ/dT 1.82 against 1.78); with the experiment's
// clock delayed by dT = 0.33 (18 ms) the largest deviation over the record is 4.1% (the issue's 5%).
TEST(IncompressibleFluid, SurgeFrontOfMartinAndMoyce) {
  const Real a = 0.05715, g = 9.81, h = a / 16;
  auto sim = test::simulation_from_yaml<2>(test::fill(R"yaml(dimension: 2
grid: {origin: [0, 0], extent: [0.6858, 0.17145], cell_size: @H@, boundary: {x_min: slip, x_max: slip, y_min: slip, y_max: slip}}
materials:
  water: {model: incompressible_fluid, density: 1000, viscosity: 1.0e-3}
bodies:
  - {name: column, material: water, shape: {type: box, min: [0, 0], max: [0.05715, 0.1143]}, particles_per_cell: 2}
solver: {scheme: musl, shape_function: linear, cfl: 0.5, gravity: [0, -9.81], end_time: 0.378}
)yaml",
                                                      {{"H", fmt::format("{:.17g}", h)}}),
                                           "martin_moyce.yaml");
  std::vector<Real> T, Z;
  sim->run([&](const Simulation<2>& s) {
    Real front = 0;
    for (Index i = 0; i < s.bodies()[0].particles.size(); ++i) front = std::max(front, s.bodies()[0].particles.x[i][0]);
    T.push_back(s.time() * std::sqrt(2 * g / a));
    Z.push_back((front + h / 4) / a);  // the edge of the last particle's domain
  });
  std::vector<std::array<Real, 2>> experiment;
  std::ifstream csv(std::string(MPM_SOURCE_DIR) + "/tests/data/dam_break_martin_moyce.csv");
  for (std::string line; std::getline(csv, line);) {
    if (line.empty() || !std::isdigit(static_cast<unsigned char>(line[0]))) continue;
    Real size, t, z;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &size, &t, &z) == 3 && size == 2.25) experiment.push_back({t, z});
  }
  ASSERT_GT(experiment.size(), 5u);
  const auto model_at = [&](Real t) {
    const auto it = std::lower_bound(T.begin(), T.end(), t);
    if (it == T.begin()) return Z.front();
    if (it == T.end()) return Z.back();
    const auto k = static_cast<std::size_t>(it - T.begin());
    return Z[k - 1] + (Z[k] - Z[k - 1]) * (t - T[k - 1]) / (T[k] - T[k - 1]);
  };
  Real best = 1e300;
  for (Real delay = 0; delay <= 1; delay += 0.005) {
    Real worst = 0;
    for (const auto& [t, z] : experiment) worst = std::max(worst, std::abs(model_at(t - delay) / z - 1));
    best = std::min(best, worst);
  }
  EXPECT_LT(best, 0.05);
  const Real speed = (model_at(6.5) - model_at(4)) / 2.5;
  EXPECT_NEAR(speed, 1.78, 0.1 * 1.78);
}

// A run saved at step 60 and restored goes on to step 120 with the same bits as the run that went through
// (positions, velocities, stresses with the projected pressure), and the projection after the restart starts
// from the same first guess (the particles' pressures are particle fields).
TEST(IncompressibleFluid, RestartsExactly) {
  const std::string yaml = closed_tank(10, "scheme: musl, shape_function: linear");
  auto reference = test::simulation_from_yaml<2>(yaml, "tank.yaml");
  reference->run({}, 60);
  StateArchive archive;
  reference->save_state(archive);
  reference->run({}, 120);
  auto restarted = test::simulation_from_yaml<2>(yaml, "tank.yaml");
  restarted->restore_state(archive);
  restarted->run({}, 120);
  const auto& a = reference->bodies()[0].particles;
  const auto& b = restarted->bodies()[0].particles;
  ASSERT_EQ(a.size(), b.size());
  Real moved = 0;
  for (Index i = 0; i < a.size(); ++i) {
    EXPECT_EQ(Vec<2>(a.x[i]), Vec<2>(b.x[i])) << i;
    EXPECT_EQ(Vec<2>(a.v[i]), Vec<2>(b.v[i])) << i;
    EXPECT_EQ(a.stress[i].full(), b.stress[i].full()) << i;
    moved = std::max(moved, Vec<2>(a.v[i]).norm());
  }
  EXPECT_GT(moved, 0.5);  // the saved state was flowing
  // it solved once per step
  const fluids::PressureProjection<2, LinearHat>* projection = nullptr;
  for (const auto& m : reference->modules())
    if (const auto* found = dynamic_cast<const fluids::PressureProjection<2, LinearHat>*>(m.get())) projection = found;
  ASSERT_NE(projection, nullptr);
  EXPECT_EQ(projection->statistics().solves, 120);
}

// A solve that does not reach projection_tolerance within projection_iterations stops the program (exit status 1, as a
// stability stop) with the step, the residual and the two keys to change; the column's first solve needs more than 3.
TEST(IncompressibleFluid, ASolveThatStopsShortStopsTheRun) {
  const auto dir = cli::scratch("incompressible_short_solve");
  std::string scene = projected_column("scheme: musl, shape_function: linear");
  scene.replace(scene.find("projection_tolerance: 1.0e-12"), 29, "projection_iterations: 3");  // default tolerance
  std::ofstream(dir / "column.yaml") << scene;
  const auto r = cli::mpm("run " + (dir / "column.yaml").string() + " -o " + (dir / "out").string(), dir);
  EXPECT_NE(r.status, 0);
  const std::string err = cli::slurp(dir / "stderr");
  EXPECT_NE(err.find("pressure projection: the conjugate gradients stopped after 3 iterations"), std::string::npos)
      << err;
  EXPECT_NE(err.find("(step 1, t = 0 s, 800 fluid cells): raise materials.water.projection_iterations"),
            std::string::npos)
      << err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mpm
