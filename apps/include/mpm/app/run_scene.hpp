#pragma once
/// \file run_scene.hpp
/// `mpm run` and `mpm check` behind the command line: build, run with output and progress, summarise.

#include <filesystem>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mpm/app/stop_signals.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/simulation/step_profile.hpp"

namespace mpm {
template <int Dim>
class Run;
class RunLog;
}  // namespace mpm

namespace mpm::app {

/// Exit statuses of the `mpm` program.
enum ExitStatus : int {
  exit_ok = 0,
  exit_runtime_error = 1,  ///< I/O failure or an internal error
  exit_bad_input = 2,      ///< invalid scene or command line
  exit_unstable = 3,       ///< the stability guard stopped the run (the last good state was written)
};

struct RunOptions {
  std::optional<std::filesystem::path> output_directory;  ///< overrides the scene's output.directory
  bool progress = false;                                  ///< progress line (on a terminal)
  bool profile = false;            ///< time the phases of every step and print the breakdown at the end (`--profile`)
  std::optional<long long> steps;  ///< stop after this many steps (`--steps`, >= 1), or at the end time if sooner
  std::optional<double> end_time;  ///< s, replaces the scene's solver.end_time (`--end-time`, > 0)
  /// Changes made to the scene before the run by its caller (`mpm verify`: the refinement), "key: value" lines
  /// recorded in the output files' field data with the command line's.
  std::vector<std::string> overrides;
  /// Continue this checkpoint, or the newest valid one of this directory (`--restart`; run_checkpoints.hpp).
  std::optional<std::filesystem::path> restart;
  /// The ranks of a distributed run (`mpirun -np N mpm run`), null in one process: the simulation is
  /// distributed over them (Simulation::distribute), and what cannot run on several ranks yet is refused
  /// (RankCountError, exit status 2, on every rank alike).
  std::shared_ptr<Communicator> communicator;
  /// Distributed run: steps between balance checks (`--rebalance-every`; SimulationSettings::rebalance_interval).
  int rebalance_every = 50;
  /// Distributed run: every scatter exchanges ghost nodes (`--exchange-every-scatter`, hidden: the benchmark's
  /// baseline; SimulationSettings::exchange_every_scatter).
  bool exchange_every_scatter = false;
  /// The test seams of the run path, hidden options of `mpm run` (apps/README.md, "Test seams"; stop_signals.hpp).
  struct TestSeams {
    std::optional<TestSignal> signal;    ///< `--test-signal-at STEP:NAME`
    std::optional<TestFailure> failure;  ///< `--test-fail-at RANK:STEP`
    int kill_in_checkpoint = 0;          ///< `--test-kill-in-checkpoint N` (RunCheckpoints::kill_in_checkpoint)
  } test;
};

struct RunSummary {
  long long steps = 0;
  double wall_seconds = 0;
  double particle_updates_per_second = 0;
  double relative_energy_change = 0;  ///< (E_end - E_0)/|E_0|
  /// The energy sentinel's largest balance / tolerance over the run (energy_sentinel.hpp; > 1: it warned), and
  /// the step of it.
  double largest_energy_ratio = 0;
  long long largest_energy_ratio_step = 0;
  std::size_t particles = 0;
  std::size_t bytes_per_particle = 0;
  StepProfile profile;  ///< per-phase wall time, with RunOptions::profile (all zero otherwise)
  /// Warnings, as logged: of the histories when they are built ("output.histories[i]: ..."), and of the
  /// materials about their state (Material::state_warning), the first of each body: "body NAME at t = ... s:
  /// MESSAGE".
  std::vector<std::string> warnings;
  /// The signal that stopped the run after it wrote a checkpoint and the last frame (stop_signals.hpp), or 0;
  /// the program then exits with 128 + it.
  int stopped_by_signal = 0;
};

/// The run of `scene` as both front ends (`mpm run`, the Python package) begin it (mpm/run/run.hpp): the simulation
/// built (build_simulation; throws SceneError), the warnings about it (a time step collapsed by a typo,
/// step_estimate.hpp) and the scene's histories. Its warnings are logged by Run::log_warnings(), its output opened by
/// Run::start(). The scene's gravity stage runs unless `restarting` (the checkpoint holds the settled state); a stage
/// that did not settle with `on_no_equilibrium: warn` is one of the warnings.
template <int Dim>
std::unique_ptr<Run<Dim>> make_run(const SceneDescription& scene, RunLog& log, bool restarting = false);

/// Builds the scene's simulation without running it (throws SceneError like load_scene). The report goes to `out`,
/// its warnings to `log` (the program's stdout and stderr: README.md, "Output streams"). `ranks` > 0 adds
/// what a distributed run on that many ranks would hold (rank_report.hpp; throws RankCountError above the tile count).
void check_scene(const SceneDescription& scene, std::ostream& out, std::ostream& log, int ranks = 0);

/// Runs the scene to its end time (or options.end_time, or options.steps steps, or until SIGINT, SIGTERM or
/// SIGUSR1), writing output and checkpoints, or continues a checkpoint (options.restart); returns the
/// summary. The summary of a run that reached its end (the outflow, energy sentinel and failure lines, "done: ...",
/// the profile) is printed to `out`; everything said on the way (restart and fork lines, warnings, notes, the
/// progress line, the time-step note, a stop by signal, the flight recorder) to `log` (the program's stdout and
/// stderr; the same stream for both keeps the order). Throws RestartError or CheckpointError for a checkpoint it
/// cannot continue. Throws SceneError for a scene that only fails once built, StabilityError (after writing the last
/// good state) if the guard trips, std::invalid_argument for steps < 1 or an end time that is not positive.
RunSummary run_scene(const SceneDescription& scene, const RunOptions& options, std::ostream& out, std::ostream& log);

}  // namespace mpm::app
