#pragma once
/// \file run_checkpoints.hpp
/// The checkpoints of one `mpm run` (docs/scene-reference.md, output.checkpoint; README "Long runs"): when
/// they are due (every `interval` of simulated time, every `wall_interval` of wall-clock time, at the end,
/// on a stop signal), what they hold besides the simulation's and the output's state (the program version,
/// the scene text and its hash, the checkpoint schedule), where they go (checkpoint_STEP.h5 in the
/// checkpoint directory, written atomically) and how many are kept. And the way back: the checkpoint a
/// restart continues, checked against this program and this scene.

#include <chrono>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/app/scene_diff.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/run/checkpoint_sink.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::app {

/// A restart that cannot go on: no valid checkpoint, another program version, a scene that differs in more
/// than run-control keys. Bad input (exit status 2); what() says what and where.
class RestartError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The scene file's text (what a checkpoint stores and a restart compares).
std::string read_scene_text(const SceneDescription& scene);

/// Where the checkpoints of a run writing to `output_directory` go: output.checkpoint.directory, or
/// OUTPUT/checkpoints.
std::filesystem::path checkpoint_directory(const SceneDescription& scene,
                                           const std::filesystem::path& output_directory);

/// The program's checkpoint sink (checkpoint_sink.hpp): HDF5 files through checkpoint/.
class RunCheckpoints final : public CheckpointSink {
 public:
  using Clock = std::chrono::steady_clock;
  /// `directory`: where checkpoints go (output.checkpoint.directory, or OUTPUT/checkpoints). With
  /// output.checkpoint in the scene, checks at once that checkpoints can be written there (SceneError at
  /// the key otherwise).
  /// Without `writes_files` (every rank but 0 of a distributed run) the schedule is kept but nothing is written,
  /// checked or removed.
  RunCheckpoints(const SceneDescription& scene, std::string scene_text, std::filesystem::path directory,
                 bool writes_files = true);

  /// A checkpoint is due after a step that reached `time` (s): its interval or its wall interval has passed.
  bool due(double time) const override;
  /// With output.checkpoint in the scene.
  bool at_end() const override { return settings_.enabled; }
  /// Adds the run's metadata and schedule to `archive` and writes it as checkpoint_STEP.h5; then removes
  /// the older checkpoints beyond `keep`. Returns the file (empty without writes_files).
  std::filesystem::path write(StateArchive& archive, Index step, double time) override;
  /// Continues the schedule of the checkpoint a restart read; removes the checkpoints of this directory
  /// that are later than it (the interrupted run's, which this run writes again). Returns their count.
  int restore(const StateArchive& archive);

  const std::filesystem::path& directory() const { return directory_; }
  /// Test seam (`mpm run --test-kill-in-checkpoint N`): the process kills itself (SIGKILL) halfway through writing
  /// its N-th checkpoint; 0: never.
  void kill_in_checkpoint(int n) { kill_in_checkpoint_ = n; }

 private:
  CheckpointDescription settings_;
  std::string scene_file_, scene_text_;
  std::vector<double> gravity_;  ///< m/s^2, a component per axis: what a fork that changes it rebases on
  std::filesystem::path directory_;
  double next_time_ = 0;
  Clock::time_point last_wall_;
  bool writes_files_ = true;
  int written_ = 0;             ///< checkpoints written
  int kill_in_checkpoint_ = 0;  ///< the test seam's
};

/// The checkpoint `mpm run SCENE --restart FILE|DIR` continues: FILE, or the newest valid checkpoint of DIR (or of
/// DIR/checkpoints, when DIR is an output directory)
/// (an invalid one, such as a file cut short by a crash, is reported in `log` and skipped). Checks that it
/// was written by this version of the program and that the scene differs from its scene only in run-control
/// keys (a fork, whose changes `changes` lists); throws RestartError otherwise, or CheckpointError when FILE
/// is not a valid checkpoint.
struct RestartPoint {
  std::filesystem::path file;
  StateArchive archive;
  std::vector<SceneDifference> changes;
};
RestartPoint find_restart_point(const std::filesystem::path& file_or_directory, const SceneDescription& scene,
                                const std::string& scene_text, std::ostream& log);

/// The name of the file in a fork's output directory that lists what the fork changed.
inline constexpr const char* fork_changes_file = "fork_changes.txt";
/// A fork (`point` with changes): writes `directory`/fork_changes.txt atomically, a line per changed key
/// ("solver.gravity: [0, 0] in the checkpoint, [0, -9.81] now  # fork.yaml:9") after a line naming the checkpoint,
/// so that the forked run's files say what it changed; nothing for a plain restart (its files are those of the
/// uninterrupted run).
void write_fork_changes(const std::filesystem::path& directory, const RestartPoint& point);

/// A fork that changed `solver.gravity` (the checkpoint's run/gravity differs from `scene`'s): the particles'
/// gravity potential -sum m g . x jumps at the checkpoint by dE = -(g_new - g_old) . sum m x (particles as saved).
/// Shifts E(0) in `point`'s archive by dE (the energy sentinel's initial gravity potential and run/initial_energy),
/// so that the audit's balance E(t) - E(0) - W and the summary's energy change continue across the change instead
/// of reading the new potential as a gain. Returns dE; 0 without a change.
double rebase_gravity_potential(RestartPoint& point, const SceneDescription& scene);

}  // namespace mpm::app
