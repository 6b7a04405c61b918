// Forks that change the physics (issue 54): a fork may change what keeps the state's meaning (boundary conditions,
// material parameters, gravity), and the change takes effect from the checkpoint on; it may not change what the
// state was built from (the grid, the bodies' particles, the scheme's or the model's state layout), each refused
// with its key, line and reason and nothing written. Every fork lists its changes in fork_changes.txt.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "restart_support.hpp"

namespace {

// qualified names: a unity batch may hold another test's helpers of the same names
namespace fs = std::filesystem;
using cli::Result;

/// A block on a fixed floor under the grid's top face `top` (a condition of grid.boundary), MUSL with PIC (so that a
/// face switched between steps gives the same bits as the fork: test_fork.cpp), checkpoint at t = 0.2 s (step 100).
std::string fork_physics_block(const std::string& top) {
  return "dimension: 2\n"
         "grid:\n"
         "  origin: [0, 0]\n"
         "  extent: [0.4, 0.4]\n"
         "  cell_size: 0.05\n"
         "  boundary: {x_min: slip, y_min: fixed, y_max: " +
         top +
         "}\n"
         "materials: {elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1000, poisson_ratio: 0.3}}\n"
         "bodies:\n"
         "  - {name: block, material: elastic, shape: {type: box, min: [0, 0], max: [0.2, 0.4]}}\n"
         "solver: {scheme: musl, shape_function: linear, flip_fraction: 0, dt: 0.002, end_time: 0.4}\n"
         "output:\n"
         "  interval: 0.05\n"
         "  fields: [velocity, stress]\n"
         "  histories: [{name: floor, type: reaction, face: y_min}]\n" +
         restart_support::checkpoint_at(0.2);
}

/// `mpm run SCENE -o OUT --restart CHECKPOINT` in `dir`.
Result fork_physics_run(const fs::path& dir, const std::string& scene, const std::string& out,
                        const fs::path& checkpoint) {
  return cli::mpm("run " + (dir / scene).string() + " -o " + (dir / out).string() + " --restart " + checkpoint.string(),
                  dir);
}

/// The last row of a CSV file with a header, by column name.
std::map<std::string, double> fork_physics_last_row(const fs::path& csv) {
  std::ifstream in(csv);
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::map<std::string, double> row;
  std::istringstream names(header), values(last);
  std::string name, value;
  while (std::getline(names, name, ',') && std::getline(values, value, ',')) row[name] = std::stod(value);
  return row;
}

TEST(ForkPhysics, SlipFaceBecomesAMovingWallFromTheCheckpointOn) {
  // Before issue 54 the fork was refused (grid.boundary.y_max is not run control). Now it continues the
  // checkpoint at T = 0.2 s with the top face moving down at 0.0625 m/s; the reference is a run whose top face
  // holds "t <= 0.201 ? 0 : -0.0625" from the start ([free, 0] is slip on y_max: normal component held at 0,
  // tangential free), which with PIC reaches the same bits (test_fork.cpp's argument).
  const fs::path dir = cli::scratch("fork_physics_face");
  std::ofstream(dir / "slip.yaml") << fork_physics_block("slip");
  std::ofstream(dir / "wall.yaml") << fork_physics_block("{velocity: [free, -0.0625]}");
  std::ofstream(dir / "switched.yaml") << fork_physics_block("{velocity: [free, \"t <= 0.201 ? 0 : -0.0625\"]}");
  ASSERT_EQ(cli::mpm("run " + (dir / "slip.yaml").string() + " -o " + (dir / "slip").string(), dir).status, 0);
  const Result switched =
      cli::mpm("run " + (dir / "switched.yaml").string() + " -o " + (dir / "switched").string(), dir);
  ASSERT_EQ(switched.status, 0) << switched.err;
  const auto steps = restart_support::checkpoint_steps(dir / "slip" / "checkpoints");
  ASSERT_EQ(steps.front(), 100);
  const Result fork =
      fork_physics_run(dir, "wall.yaml", "fork", dir / "slip" / "checkpoints" / mpm::checkpoint::checkpoint_name(100));
  ASSERT_EQ(fork.status, 0) << fork.err;
  const std::string change = "grid.boundary.y_max: slip in the checkpoint, {velocity: [free, -0.0625]} now";
  EXPECT_NE(fork.err.find("fork: " + (dir / "wall.yaml").string() + ":6: " + change), std::string::npos) << fork.err;
  // The fork's files say what it changed.
  const std::string listed = cli::slurp(dir / "fork" / "fork_changes.txt");
  EXPECT_NE(listed.find(change + "  # " + (dir / "wall.yaml").string() + ":6\n"), std::string::npos) << listed;
  // The wall moved from T on: every frame (t = 0 to 0.4 s) by value and the floor's reaction as the switched run's.
  const Result same = cli::mpm(
      "diff " + (dir / "switched").string() + " " + (dir / "fork").string() + " --tolerance 0 --absolute 0", dir);
  EXPECT_EQ(same.status, 0) << same.out << same.err;
  EXPECT_EQ(cli::slurp(dir / "fork" / "floor.csv"), cli::slurp(dir / "switched" / "floor.csv"));
  // ... and not as the slip face would have: the block is pressed (its particles' velocities differ by up to
  // the wall's 0.0625 m/s).
  EXPECT_EQ(
      cli::mpm("diff " + (dir / "slip").string() + " " + (dir / "fork").string() + " --absolute 1e-9", dir).status, 1);
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(ForkPhysics, ChangedYoungsModulusSetsTheTimeStepOfTheFork) {
  // A block moving at 0.1 m/s in a free grid, adaptive step cfl 0.5: dt = cfl h / (c + |v|) with the dilatational
  // speed c = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu)) / rho) (eq. 2.73). The fork from the checkpoint at T (about
  // 0.1 s) quadruples E, so c doubles and the steps from T to the end are those of dt(4E): 292.3 instead of 146.3
  // (the first step of the fork takes the checkpoint's wave speed, and steps round up: within 2 steps).
  // Before issue 54 the fork was refused (materials.elastic.youngs_modulus is not run control).
  const fs::path dir = cli::scratch("fork_physics_modulus");
  const auto scene = [](const std::string& modulus) {
    return "dimension: 2\n"
           "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
           "materials: {elastic: {model: linear_elastic, density: 1000, youngs_modulus: " +
           modulus +
           ", poisson_ratio: 0.3}}\n"
           "bodies:\n"
           "  - {name: block, material: elastic, shape: {type: box, min: [0.3, 0.3], max: [0.7, 0.7]}, "
           "velocity: [0.1, 0]}\n"
           "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 0.2}\n"
           "output:\n"
           "  interval: 0.05\n" +
           restart_support::checkpoint_at(0.1);
  };
  std::ofstream(dir / "soft.yaml") << scene("1e6");
  std::ofstream(dir / "stiff.yaml") << scene("4e6");
  const Result soft = cli::mpm("run " + (dir / "soft.yaml").string() + " -o " + (dir / "soft").string(), dir);
  ASSERT_EQ(soft.status, 0) << soft.err;
  const auto steps = restart_support::checkpoint_steps(dir / "soft" / "checkpoints");
  ASSERT_EQ(steps.size(), 2u);
  const fs::path checkpoint = dir / "soft" / "checkpoints" / mpm::checkpoint::checkpoint_name(steps[0]);
  const double t = mpm::checkpoint::read_checkpoint(checkpoint).number("simulation/time");
  const Result fork = fork_physics_run(dir, "stiff.yaml", "fork", checkpoint);
  ASSERT_EQ(fork.status, 0) << fork.err;
  EXPECT_NE(fork.err.find(":3: materials.elastic.youngs_modulus: 1e6 in the checkpoint, 4e6 now"), std::string::npos)
      << fork.err;
  EXPECT_NE(
      cli::slurp(dir / "fork" / "fork_changes.txt").find("materials.elastic.youngs_modulus: 1e6 in the checkpoint"),
      std::string::npos);
  const double nu = 0.3, rho = 1000, h = 0.05, v = 0.1, cfl = 0.5;
  const auto steps_to_end = [&](double youngs) {
    const double c = std::sqrt(youngs * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho);
    return (0.2 - t) / (cfl * h / (c + v));
  };
  EXPECT_NEAR(static_cast<double>(restart_support::steps_done(soft) - steps[0]), steps_to_end(1e6), 2.0);
  EXPECT_NEAR(static_cast<double>(restart_support::steps_done(fork) - steps[0]), steps_to_end(4e6), 2.0);
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(ForkPhysics, GravitySwitchedOnMakesTheBlockFallFromTheCheckpoint) {
  // A block of 0.2 m x 0.2 m x 1000 kg/m^3 = 40 kg (per metre) at rest, free in the grid, without gravity to
  // T = 0.05 s; the fork switches gravity on. A free body under uniform gravity moves rigidly (no stress): every
  // node and particle gains g dt per step, so at t = 0.1 s its momentum is M g (t - T) = 19.62 kg m/s down and
  // its kinetic energy M (g (t - T))^2 / 2 = 4.811805 J (round-off only). The run without the fork stays at rest.
  // Before issue 54 the fork was refused (solver.gravity is not run control).
  const fs::path dir = cli::scratch("fork_physics_gravity");
  const auto scene = [](const std::string& gravity) {
    return "dimension: 2\n"
           "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.05}\n"
           "materials: {elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1e6, poisson_ratio: 0.3}}\n"
           "bodies:\n"
           "  - {name: block, material: elastic, shape: {type: box, min: [0.4, 0.6], max: [0.6, 0.8]}}\n"
           "solver: {scheme: musl, shape_function: linear, dt: 0.001, end_time: 0.1, gravity: " +
           gravity +
           "}\n"
           "output:\n"
           "  interval: 0.05\n" +
           restart_support::checkpoint_at(0.05);
  };
  std::ofstream(dir / "still.yaml") << scene("[0, 0]");
  std::ofstream(dir / "falling.yaml") << scene("[0, -9.81]");
  ASSERT_EQ(cli::mpm("run " + (dir / "still.yaml").string() + " -o " + (dir / "still").string(), dir).status, 0);
  const auto steps = restart_support::checkpoint_steps(dir / "still" / "checkpoints");
  ASSERT_EQ(steps.size(), 2u);
  const fs::path checkpoint = dir / "still" / "checkpoints" / mpm::checkpoint::checkpoint_name(steps[0]);
  const double t0 = mpm::checkpoint::read_checkpoint(checkpoint).number("simulation/time");
  const Result fork = fork_physics_run(dir, "falling.yaml", "fork", checkpoint);
  ASSERT_EQ(fork.status, 0) << fork.err;
  EXPECT_NE(fork.err.find(":6: solver.gravity[1]: 0 in the checkpoint, -9.81 now"), std::string::npos) << fork.err;
  // The potential -sum m g . x jumps at T by M 9.81 m/s^2 0.7 m (the block's centre) = 274.68 J; E(0) of the energy
  // audit moves with it, so the audit sees no gain (without the shift it warned: balance +274.6 J).
  EXPECT_NE(fork.err.find("fork: the gravity potential jumps by +274.68 J"), std::string::npos) << fork.err;
  EXPECT_EQ(fork.err.find("warning: energy sentinel"), std::string::npos) << fork.err;
  EXPECT_NE(cli::slurp(dir / "fork" / "fork_changes.txt").find("solver.gravity[1]: 0 in the checkpoint, -9.81 now"),
            std::string::npos);
  const auto still = fork_physics_last_row(dir / "still" / "energy.csv");
  const auto fell = fork_physics_last_row(dir / "fork" / "energy.csv");
  EXPECT_EQ(still.at("kinetic_energy"), 0.0);
  const double mass = 40, fall_time = fell.at("time") - t0, speed = 9.81 * fall_time;
  EXPECT_NEAR(fall_time, 0.05, 1e-12);
  EXPECT_NEAR(fell.at("mass"), mass, 1e-12);
  EXPECT_NEAR(fell.at("momentum_y"), -mass * speed, 1e-9 * mass * speed);
  EXPECT_NEAR(fell.at("momentum_x"), 0.0, 1e-12);
  EXPECT_NEAR(fell.at("kinetic_energy"), 0.5 * mass * speed * speed, 1e-9 * mass * speed * speed);
  if (!HasFailure()) fs::remove_all(dir);
}

/// The regular files below `dir` (none when it does not exist).
int fork_physics_files_below(const fs::path& dir) {
  int files = 0;
  if (fs::exists(dir))
    for (const auto& e : fs::recursive_directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
  return files;
}

TEST(ForkPhysics, WhatTheStateWasBuiltFromIsRefusedWithItsReason) {
  // Each change is refused (exit status 2) with its file, line, key, both values and the reason of its class (a
  // face made outflow, which the key's spec allows, by the restore: the checkpoint names it);
  // the fork's output directory gets no file (as for every refusal: its checkpoint directory is created empty by
  // the writability check before the restart is read). Before issue 54 the same keys were refused, without a
  // reason.
  const fs::path dir = cli::scratch("fork_physics_refused");
  const std::string scene = fork_physics_block("slip");
  std::ofstream(dir / "scene.yaml") << scene;
  ASSERT_EQ(cli::mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string(), dir).status, 0);
  const fs::path checkpoint = dir / "out" / "checkpoints" / mpm::checkpoint::checkpoint_name(100);
  struct Refused {
    std::string name, from, to, line;
  };
  const std::vector<Refused> cases{
      {"cell_size", "cell_size: 0.05", "cell_size: 0.025",
       ":5: grid.cell_size: 0.05 in the checkpoint, 0.025 now: the grid is the checkpoint's"},
      {"shape", "max: [0.2, 0.4]", "max: [0.15, 0.4]",
       ":9: bodies[0].shape.max[0]: 0.2 in the checkpoint, 0.15 now: the bodies' particles come from the checkpoint"},
      {"scheme", "scheme: musl", "scheme: usl",
       ":10: solver.scheme: musl in the checkpoint, usl now: the state layout of the scheme"},
      {"model", "model: linear_elastic", "model: neo_hookean",
       ":7: materials.elastic.model: linear_elastic in the checkpoint, neo_hookean now: the state layout of the model"},
      {"outflow", "x_min: slip", "x_min: outflow",
       ": does not fit the scene: the outflow faces differ: [] in the checkpoint, [x_min] in the scene; a fork may "
       "not add or remove an outflow face"},
      {"density", "density: 1000", "density: 2000",
       ":7: materials.elastic.density: 1000 in the checkpoint, 2000 now: the particles' masses come from the "
       "checkpoint"},
  };
  for (const auto& c : cases) {
    const std::string file = c.name + ".yaml";
    std::ofstream(dir / file) << restart_support::replaced(scene, c.from, c.to);
    const Result r = fork_physics_run(dir, file, "fork_" + c.name, checkpoint);
    EXPECT_EQ(r.status, 2) << c.name << "\n" << r.err;
    const std::string where = c.line.starts_with(": does not fit") ? checkpoint.string() : (dir / file).string();
    EXPECT_NE(r.err.find(where + c.line), std::string::npos) << c.name << "\n" << r.err;
    EXPECT_EQ(fork_physics_files_below(dir / ("fork_" + c.name)), 0) << c.name;
  }
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
