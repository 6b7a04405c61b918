// The run object (libmpm/include/mpm/run/run.hpp) on its own, with a log and a checkpoint sink that record what
// they are given: when it checkpoints, what a checkpoint holds, how an observer stops or interrupts it, and that
// the materials' state warning is logged once. The same policy through both front ends: test_energy_drift_stop.cpp
// and python/tests/test_run_policy.py.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/run_scene.hpp"
#include "mpm/run/run.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "run_mpm.hpp"

namespace {

namespace fs = std::filesystem;

/// Every line the run logs.
struct RecordingLog final : mpm::RunLog {
  std::vector<std::string> lines;
  void line(const std::string& text) override { lines.push_back(text); }
};

/// A checkpoint every `interval` s of simulated time (and at the end), recorded: the steps and the last archive
/// (an empty file stands for each checkpoint).
struct RecordingSink final : mpm::CheckpointSink {
  fs::path directory;
  double interval = 0.1, next = 0.1;
  std::vector<mpm::Index> steps;
  mpm::StateArchive last;
  bool due(double time) const override { return time >= next * (1 - 1e-12); }
  bool at_end() const override { return true; }
  fs::path write(mpm::StateArchive& archive, mpm::Index step, double time) override {
    while (next <= time * (1 + 1e-12)) next += interval;
    steps.push_back(step);
    last = archive;
    const fs::path file = directory / ("checkpoint_" + std::to_string(step));
    std::ofstream(file) << "";
    return file;
  }
};

/// Interrupts the run at one step, or stops it after one step.
struct StopAt final : mpm::RunObserver<2> {
  mpm::Index interrupt = -1, stop = -1;
  int steps_seen = 0;
  bool interrupt_requested(mpm::Index step) override { return step == interrupt; }
  bool after_step(const mpm::Simulation<2>& sim) override {
    ++steps_seen;
    return sim.step() == stop;
  }
};

/// Two elastic disks on a 10 x 10 grid, dt = 0.002 s to t = 0.5 s (250 steps), a frame every 0.1 s.
mpm::SceneDescription two_disks() {
  return mpm::parse_scene(
      "dimension: 2\n"
      "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.1}\n"
      "materials: {elastic: {model: linear_elastic, density: 1000, youngs_modulus: 1000, poisson_ratio: 0.3}}\n"
      "bodies:\n"
      "  - {name: lower_left, material: elastic, shape: {type: disk, center: [0.3, 0.3], radius: 0.15}, "
      "velocity: [0.1, 0.1]}\n"
      "  - {name: upper_right, material: elastic, shape: {type: disk, center: [0.7, 0.7], radius: 0.15}, "
      "velocity: [-0.1, -0.1]}\n"
      "solver: {scheme: musl, shape_function: linear, dt: 0.002, end_time: 0.5}\n"
      "output: {interval: 0.1, fields: [velocity]}\n",
      "disks.yaml");
}

struct Fixture {
  fs::path dir = cli::scratch("run_object");
  RecordingLog log;
  RecordingSink sink;
  std::unique_ptr<mpm::Run<2>> run;
  explicit Fixture(const mpm::SceneDescription& scene, bool checkpoints = true) {
    sink.directory = dir;
    run = mpm::app::make_run<2>(scene, log);
    mpm::RunOutput output;
    output.directory = dir / "out";
    output.checkpoints = checkpoints ? &sink : nullptr;
    run->start(output);
  }
  ~Fixture() {
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
  }
  /// The frames written, by the lines of the .pvd.
  int frames() const {
    int n = 0;
    std::ifstream in(dir / "out" / "particles.pvd");
    for (std::string line; std::getline(in, line);) n += line.find("<DataSet") != std::string::npos;
    return n;
  }
};

TEST(RunObject, CheckpointsWhenTheSinkSaysAndAtTheEnd) {
  Fixture f(two_disks());
  EXPECT_EQ(f.run->run(), mpm::RunEnd::end_time);
  // t = 0.1, 0.2, 0.3, 0.4 s (steps 50 .. 200), then the end (250): one per step at most, the end's once
  EXPECT_EQ(f.sink.steps, (std::vector<mpm::Index>{50, 100, 150, 200, 250}));
  EXPECT_EQ(f.sink.last.integer("simulation/step"), 250);
  EXPECT_EQ(f.sink.last.integer("output/frame"), 6);  // t = 0, 0.1, ..., 0.5
  EXPECT_EQ(f.sink.last.values<std::int8_t>("run/warned"), (std::vector<std::int8_t>{0, 0}));
  EXPECT_TRUE(f.sink.last.contains("run/initial_energy"));
  EXPECT_EQ(f.frames(), 6);
  ASSERT_EQ(f.log.lines.size(), 5u);
  EXPECT_EQ(f.log.lines[0].rfind("checkpoint: " + (f.dir / "checkpoint_50").string() + " (step 50, t = 0.1 s; ", 0), 0u)
      << f.log.lines[0];
  EXPECT_EQ(f.run->last_checkpoint(), f.dir / "checkpoint_250");
}

TEST(RunObject, AnInterruptWritesACheckpointAndTheLastFrame) {
  Fixture f(two_disks());
  StopAt observer;
  observer.interrupt = 7;
  EXPECT_EQ(f.run->run({}, &observer), mpm::RunEnd::interrupted);
  EXPECT_EQ(f.run->simulation().step(), 7);
  EXPECT_EQ(observer.steps_seen, 6);  // not after the interrupted step
  EXPECT_EQ(f.sink.steps, std::vector<mpm::Index>{7});
  EXPECT_EQ(f.frames(), 2);  // t = 0 and the step it stopped after
}

TEST(RunObject, AnObserverStopsAfterItsStepWithoutACheckpoint) {
  Fixture f(two_disks());
  StopAt observer;
  observer.stop = 3;
  EXPECT_EQ(f.run->run({}, &observer), mpm::RunEnd::stopped);
  EXPECT_EQ(f.run->simulation().step(), 3);
  EXPECT_TRUE(f.sink.steps.empty());
  EXPECT_EQ(f.frames(), 2);
  // and goes on from there: a step limit (absolute), then the end
  EXPECT_EQ(f.run->run(10), mpm::RunEnd::step_limit);
  EXPECT_EQ(f.run->simulation().step(), 10);
  EXPECT_EQ(f.run->advance_to(0.5), mpm::RunEnd::end_time);
  EXPECT_EQ(f.run->simulation().step(), 250);
  EXPECT_EQ(f.sink.steps, (std::vector<mpm::Index>{50, 100, 150, 200, 250}));
}

TEST(RunObject, StepByStepEndsTheRunOnTheStepThatReachesTheEnd) {
  Fixture f(two_disks());
  while (f.run->step() != mpm::RunEnd::end_time) ASSERT_LT(f.run->simulation().step(), 250);
  EXPECT_EQ(f.run->simulation().step(), 250);
  EXPECT_EQ(f.sink.steps, (std::vector<mpm::Index>{50, 100, 150, 200, 250}));
  EXPECT_EQ(f.frames(), 6);
}

TEST(RunObject, WithoutADirectoryItWritesNothing) {
  const fs::path dir = cli::scratch("run_object_nothing");
  RecordingLog log;
  RecordingSink sink;
  sink.directory = dir;
  auto run = mpm::app::make_run<2>(two_disks(), log);
  mpm::RunOutput output;
  output.checkpoints = &sink;  // a checkpoint holds the output's state: none without output
  run->start(output);
  EXPECT_EQ(run->run(), mpm::RunEnd::end_time);
  EXPECT_TRUE(sink.steps.empty());
  EXPECT_TRUE(run->output_directory().empty());
  EXPECT_TRUE(fs::is_empty(dir));
  run->write_frame(dir / "frames");  // a frame on request
  EXPECT_TRUE(fs::exists(dir / "frames" / "particles_000000.vtu"));
  EXPECT_TRUE(fs::exists(dir / "frames" / "view.py"));
  fs::remove_all(dir);
}

#ifdef MPM_WITH_FLUIDS
// A water column whose bulk modulus (5 kPa) is far too small for its weight: it compresses by more than the
// density tolerance (1%) within the first 50 steps. The warning is logged once and kept in the record.
TEST(RunObject, TheMaterialsStateWarningIsLoggedOnce) {
  mpm::app::register_modules();
  Fixture f(mpm::parse_scene(
                "dimension: 2\n"
                "grid: {origin: [0, 0], extent: [0.4, 0.4], cell_size: 0.02, boundary: {x_min: slip, x_max: slip, "
                "y_min: slip}}\n"
                "materials: {water: {model: newtonian_fluid, density: 1000, bulk_modulus: 5.0e3, viscosity: "
                "1.0e-3}}\n"
                "bodies: [{name: column, material: water, shape: {type: box, min: [0, 0], max: [0.4, 0.2]}}]\n"
                "solver: {cfl: 0.5, gravity: [0, -9.81], end_time: 0.3}\n"
                "output: {fields: []}\n",
                "soft.yaml"),
            false);
  EXPECT_EQ(f.run->run(), mpm::RunEnd::end_time);
  ASSERT_EQ(f.log.lines.size(), 1u);
  EXPECT_EQ(f.log.lines[0].rfind("warning: body column at t = ", 0), 0u) << f.log.lines[0];
  EXPECT_NE(f.log.lines[0].find("raise bulk_modulus"), std::string::npos) << f.log.lines[0];
  EXPECT_EQ(f.run->record().warnings, std::vector<std::string>{f.log.lines[0].substr(9)});
  EXPECT_EQ(f.run->record().warned, std::vector<bool>{true});
}
#endif

}  // namespace
