// Forks (`mpm run CHANGED_SCENE --restart CHECKPOINT`): a scene that changes only run-control keys continues the
// checkpoint, here into another output directory, and reaches the bits of a run that had those keys from the
// start (a changed end time) or from the checkpoint time on (a changed face velocity, against a run with a
// time-switched expression); a change of what the state was built from is refused with its key, line and reason
// (test_fork_physics.cpp: the forks that change the physics).
#include <gtest/gtest.h>

#include <fstream>

#include "restart_support.hpp"

namespace {

using namespace restart_support;

TEST(Fork, ChangedEndTimeContinuesIntoAnotherDirectory) {
  const fs::path dir = scratch("fork_end_time");
  const std::string scene = two_disks().scene;  // end_time 0.4, checkpoint at 0.2
  const std::string longer = replaced(scene, "end_time: 0.4", "end_time: 0.6");
  std::ofstream(dir / "scene.yaml") << scene;
  std::ofstream(dir / "longer.yaml") << longer;
  ASSERT_EQ(cli::mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "original").string(), dir).status, 0);
  const Result whole = cli::mpm("run " + (dir / "longer.yaml").string() + " -o " + (dir / "whole").string(), dir);
  ASSERT_EQ(whole.status, 0) << whole.err;
  const auto steps = checkpoint_steps(dir / "original" / "checkpoints");
  ASSERT_EQ(steps.size(), 2u);
  const std::string original_energy = slurp(dir / "original" / "energy.csv");
  const fs::path checkpoint = dir / "original" / "checkpoints" / mpm::checkpoint::checkpoint_name(steps[0]);
  const Result fork = cli::mpm(
      "run " + (dir / "longer.yaml").string() + " -o " + (dir / "fork").string() + " --restart " + checkpoint.string(),
      dir);
  ASSERT_EQ(fork.status, 0) << fork.err;
  EXPECT_NE(
      fork.err.find("fork: " + (dir / "longer.yaml").string() + ":7: solver.end_time: 0.4 in the checkpoint, 0.6 now"),
      std::string::npos)
      << fork.err;
  // The original series is untouched; the fork's energy.csv holds the original's rows up to the checkpoint and
  // then the same rows as the run that had end_time 0.6 from the start.
  EXPECT_EQ(slurp(dir / "original" / "energy.csv"), original_energy);
  EXPECT_EQ(slurp(dir / "fork" / "energy.csv"), slurp(dir / "whole" / "energy.csv"));
  // Its frames after the checkpoint are the whole run's; the earlier ones it lists from the original directory.
  // (by value: their field data name the run's command line; `mpm diff` follows the fork's .pvd, so it also
  // compares the original's frames it lists with the whole run's).
  int frames = 0;
  for (const auto& f : output_files(dir / "fork")) frames += f.ends_with(".vtu") ? 1 : 0;
  EXPECT_GE(frames, 8);  // t = 0.25, 0.3, ..., 0.6
  const Result diff =
      cli::mpm("diff " + (dir / "whole").string() + " " + (dir / "fork").string() + " --tolerance 0 --absolute 0", dir);
  EXPECT_EQ(diff.status, 0) << diff.out << diff.err;
  EXPECT_NE(slurp(dir / "fork" / "particles.pvd").find("../original/particles_000000.vtu"), std::string::npos);
  const auto a = mpm::checkpoint::read_checkpoint(dir / "whole" / "checkpoints" /
                                                  mpm::checkpoint::checkpoint_name(steps_done(whole)));
  const auto b = mpm::checkpoint::read_checkpoint(dir / "fork" / "checkpoints" /
                                                  mpm::checkpoint::checkpoint_name(steps_done(whole)));
  for (const auto& [key, array] : a.entries()) {
    if (key.rfind("bodies/", 0) != 0) continue;
    EXPECT_TRUE(b.at(key).bytes == array.bytes) << key;
  }
  if (!HasFailure()) fs::remove_all(dir);
}

/// A block on a fixed floor pressed by the top face of the grid moving down at `top` (m/s; free along x), MUSL
/// with `flip` (the flip_fraction), checkpoint at t = 0.2 s (step 100 of dt = 0.002 s).
std::string pressed_block(const std::string& top, const std::string& flip) {
  return "dimension: 2\n"
         "grid:\n"
         "  origin: [0, 0]\n"
         "  extent: [0.4, 0.4]\n"
         "  cell_size: 0.05\n"
         "  boundary: {x_min: slip, y_min: fixed, y_max: {velocity: [free, \"" +
         top +
         "\"]}}\n"
         "materials: {elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1000, poisson_ratio: 0.3}}\n"
         "bodies:\n"
         "  - {name: block, material: elastic, shape: {type: box, min: [0, 0], max: [0.2, 0.4]}}\n"
         "solver: {scheme: musl, shape_function: linear, flip_fraction: " +
         flip +
         ", dt: 0.002, end_time: 0.4}\n"
         "output:\n"
         "  interval: 0.05\n"
         "  fields: [velocity, stress]\n"
         "  histories: [{name: floor, type: reaction, face: y_min}]\n" +
         checkpoint_at(0.2);
}

TEST(Fork, ChangedFaceVelocityIsTheSwitchedExpressionFromTheCheckpointOn) {
  // The fork continues the checkpoint at T = 0.2 s with the top face at -0.125 m/s instead of -0.0625 m/s. The
  // run with the velocity "t <= 0.201 ? -0.0625 : -0.125" (0.201: between T and T + dt, away from the round-off
  // of the summed time) takes the checkpoint's value at T and the new one after: in the step from T - dt to T
  // the face ends at -0.0625 in both runs; in the step from T to T + dt it starts at -0.0625 in the expression
  // run and at -0.125 in the fork, which only the FLIP increment (v(T + dt) - v(T) on the face nodes) and a
  // reaction history of that face see (docs/scene-reference.md, "Restart and fork"). With PIC (flip_fraction 0)
  // the two runs are the same bits.
  const fs::path dir = scratch("fork_face_velocity");
  for (const std::string flip : {"0", "1"}) {
    const fs::path run = dir / ("flip_" + flip);
    fs::create_directories(run);
    std::ofstream(run / "slow.yaml") << pressed_block("-0.0625", flip);
    std::ofstream(run / "fast.yaml") << pressed_block("-0.125", flip);
    std::ofstream(run / "switched.yaml") << pressed_block("t <= 0.201 ? -0.0625 : -0.125", flip);
    ASSERT_EQ(cli::mpm("run " + (run / "slow.yaml").string() + " -o " + (run / "slow").string(), run).status, 0);
    const Result switched =
        cli::mpm("run " + (run / "switched.yaml").string() + " -o " + (run / "switched").string(), run);
    ASSERT_EQ(switched.status, 0) << switched.err;
    const auto steps = checkpoint_steps(run / "slow" / "checkpoints");
    ASSERT_EQ(steps.front(), 100);
    const fs::path checkpoint = run / "slow" / "checkpoints" / mpm::checkpoint::checkpoint_name(steps.front());
    const Result fork = cli::mpm(
        "run " + (run / "fast.yaml").string() + " -o " + (run / "fork").string() + " --restart " + checkpoint.string(),
        run);
    ASSERT_EQ(fork.status, 0) << fork.err;
    EXPECT_NE(fork.err.find("grid.boundary.y_max.velocity[1]: -0.0625 in the checkpoint, -0.125 now"),
              std::string::npos)
        << fork.err;
    const Result diff = cli::mpm(
        "diff " + (run / "switched").string() + " " + (run / "fork").string() + " --tolerance 0 --absolute 0", run);
    if (flip == "0") {
      // The same bits: every frame (t = 0 to 0.4 s) by value, energy.csv and the floor's reaction byte for byte.
      EXPECT_EQ(diff.status, 0) << diff.out << diff.err;
      EXPECT_EQ(slurp(run / "fork" / "energy.csv"), slurp(run / "switched" / "energy.csv"));
      EXPECT_EQ(slurp(run / "fork" / "floor.csv"), slurp(run / "switched" / "floor.csv"));
    } else {
      // FLIP: the particles under the face keep the jump in the expression run (their velocity grows by
      // sum N_I (-0.125 + 0.0625) in the step after T), not in the fork; the frames up to T are equal.
      EXPECT_EQ(diff.status, 1) << diff.out << diff.err;
      EXPECT_NE(diff.out.find("velocity"), std::string::npos) << diff.out;
    }
    // The fork really changed the face: the run at -0.0625 throughout ends elsewhere.
    EXPECT_EQ(
        cli::mpm("diff " + (run / "slow").string() + " " + (run / "fork").string() + " --absolute 1e-9", run).status,
        1);
  }
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(Fork, ChangedDensityOrBodyIsRefusedWithItsKeysAndLines) {
  const fs::path dir = scratch("fork_refused");
  const std::string scene = two_disks().scene;
  std::ofstream(dir / "scene.yaml") << scene;
  ASSERT_EQ(cli::mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string(), dir).status, 0);
  const std::string energy = slurp(dir / "out" / "energy.csv"), pvd = slurp(dir / "out" / "particles.pvd");
  std::string changed = replaced(scene, "density: 1000", "density: 2000");
  changed = replaced(changed, "radius: 0.15}, velocity: [-0.5", "radius: 0.1}, velocity: [-0.5");
  changed = replaced(changed, "end_time: 0.4", "end_time: 0.5");  // allowed, and not listed
  std::ofstream(dir / "changed.yaml") << changed;
  const Result r = cli::mpm("run " + (dir / "changed.yaml").string() + " -o " + (dir / "out").string() + " --restart " +
                                (dir / "out" / "checkpoints").string(),
                            dir);
  EXPECT_EQ(r.status, 2) << r.err;
  const std::string file = (dir / "changed.yaml").string();
  EXPECT_NE(
      r.err.find(file + ":3: materials.elastic.density: 1000 in the checkpoint, 2000 now: the particles' masses come "
                        "from the checkpoint"),
      std::string::npos)
      << r.err;
  EXPECT_NE(
      r.err.find(file + ":6: bodies[1].shape.radius: 0.15 in the checkpoint, 0.1 now: the bodies' particles come from "
                        "the checkpoint"),
      std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("end_time"), std::string::npos);  // allowed: not listed
  EXPECT_EQ(slurp(dir / "out" / "energy.csv"), energy);  // nothing overwritten
  EXPECT_EQ(slurp(dir / "out" / "particles.pvd"), pvd);
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
