// Forks (`mpm run CHANGED_SCENE --restart CHECKPOINT`): a scene that changes only run-control keys continues the
// checkpoint, here into another output directory, and reaches the bits of a run that had those keys from the
// start; any other change is refused with its key and line.
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

TEST(Fork, ChangedMaterialOrBodyIsRefusedWithItsKeysAndLines) {
  const fs::path dir = scratch("fork_refused");
  const std::string scene = two_disks().scene;
  std::ofstream(dir / "scene.yaml") << scene;
  ASSERT_EQ(cli::mpm("run " + (dir / "scene.yaml").string() + " -o " + (dir / "out").string(), dir).status, 0);
  const std::string energy = slurp(dir / "out" / "energy.csv"), pvd = slurp(dir / "out" / "particles.pvd");
  std::string changed = replaced(scene, "youngs_modulus: 1000", "youngs_modulus: 2000");
  changed = replaced(changed, "radius: 0.15}, velocity: [-0.5", "radius: 0.1}, velocity: [-0.5");
  changed = replaced(changed, "end_time: 0.4", "end_time: 0.5");  // allowed, and not listed
  std::ofstream(dir / "changed.yaml") << changed;
  const Result r = cli::mpm("run " + (dir / "changed.yaml").string() + " -o " + (dir / "out").string() + " --restart " +
                                (dir / "out" / "checkpoints").string(),
                            dir);
  EXPECT_EQ(r.status, 2) << r.err;
  const std::string file = (dir / "changed.yaml").string();
  EXPECT_NE(r.err.find(file + ":3: materials.elastic.youngs_modulus: 1000 in the checkpoint, 2000 now"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(file + ":6: bodies[1].shape.radius: 0.15 in the checkpoint, 0.1 now"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("end_time"), r.err.find("end_time, cfl"));  // named only in the list of what may change
  EXPECT_EQ(slurp(dir / "out" / "energy.csv"), energy);            // nothing overwritten
  EXPECT_EQ(slurp(dir / "out" / "particles.pvd"), pvd);
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
