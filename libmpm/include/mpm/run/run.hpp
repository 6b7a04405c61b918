#pragma once
/// \file run.hpp
/// One run of a scene, as `mpm run` and the Python package both drive it, so that a scene behaves the same under
/// both: the same files, the same warnings, the same stops. The run owns the simulation and the policy around its
/// steps:
///   - the output: the frames and energy.csv (OutputWriter), the histories (HistoryWriter), the scheme's per-step
///     table (solver.csv of the implicit scheme), view.py; frames to other directories on request (write_frame);
///   - the checks: the materials' state warnings (Material::state_warning) every `state_check_interval` steps and
///     at the end, the first of each body logged once; the energy sentinel's drift (energy_sentinel.hpp), logged as
///     a warning, or with `solver.on_energy_drift: stop` thrown as a StabilityError (field "energy_balance"); the
///     first departure of each body through each outflow face (boundary/grid_boundary.hpp), a warning;
///   - the gravity stage's report (gravity_stage.hpp), when the builder ran one: its summary in the log and
///     gravity_stage.csv (one row per step of the stage);
///   - the checkpoints: when a sink (checkpoint_sink.hpp) is given, one after every step it says is due, one at the
///     end, and one when the run is interrupted; each holds the run record (run_record.hpp) too.
/// Messages go to one RunLog (run_log.hpp); progress, stop requests and the flight recorder are the front end's,
/// through a RunObserver (run_observer.hpp).
///
/// A run is made in two stages: the constructor builds the scene's histories on the simulation (their modules join
/// it, so a restart must restore the simulation after it); start() then opens the output, after the front end has
/// restored a checkpoint into the simulation or distributed it over ranks.

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mpm/history/history_writer.hpp"
#include "mpm/io/csv_log.hpp"
#include "mpm/io/view_script.hpp"
#include "mpm/io/vtk_writer.hpp"
#include "mpm/output/output_writer.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/run/checkpoint_sink.hpp"
#include "mpm/run/run_log.hpp"
#include "mpm/run/run_observer.hpp"
#include "mpm/run/run_record.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/simulation/gravity_stage.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm {

/// Where and how a run writes (Run::start).
struct RunOutput {
  std::filesystem::path directory;  ///< where the frames go; empty: the run writes nothing (no checkpoints either)
  io::FieldData field_data;         ///< what every file carries (the scene, the program, the command line's changes)
  io::ViewScript view_script;       ///< view.py of the directory (and of every write_frame() directory)
  /// The checkpoint the simulation was restored from, or null: the series, the histories and the record continue it,
  /// and no first frame is written (the run's frames up to the checkpoint are there).
  const StateArchive* restart = nullptr;
  /// A distributed run's ranks (not owned), or null: a piece per rank and a .pvtu per frame; rank 0 writes the
  /// histories, the step log and view.py.
  Communicator* comm = nullptr;
  CheckpointSink* checkpoints = nullptr;  ///< not owned; null: no checkpoints
  bool profile = false;                   ///< time the phases of every step and the output (Simulation::profile)
  /// Keep every row of the histories in memory (Run::histories(), the Python package's Simulation.histories),
  /// also when the run writes no files. Off for `mpm run`: a history written every step of a long run would
  /// hold its whole table.
  bool keep_history_rows = false;
};

/// How a stepping call of Run ended.
enum class RunEnd {
  end_time,     ///< the simulation reached its end time
  step_limit,   ///< the step limit or target time of the call was reached first
  stopped,      ///< the observer's after_step() asked to stop
  interrupted,  ///< the observer's interrupt_requested() asked to stop: a checkpoint was written
};

template <int Dim>
class Run {
 public:
  /// Steps between the materials' state checks (besides the one at the end).
  static constexpr Index state_check_interval = 50;

  /// Takes the built simulation of `scene` (a copy is kept: the histories point into it) and builds the scene's
  /// histories on it (throws SceneError like the builder, naming the key). `warnings`: the front end's warnings
  /// about the built scene (the step estimate), which log_warnings() logs before the histories'.
  /// `gravity_stage`: the report of the gravity stage the builder ran on `sim` (gravity_stage.hpp), if it ran:
  /// start() logs its summary and writes gravity_stage.csv.
  Run(const SceneDescription& scene, std::unique_ptr<Simulation<Dim>> sim, RunLog& log,
      std::vector<std::string> warnings = {}, std::optional<GravityStageReport> gravity_stage = {});
  ~Run();
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;

  /// Logs the warnings of the built scene (the front end's, then the histories'), each "warning: MESSAGE".
  void log_warnings();
  /// Opens the output (writers, histories' CSVs, the step log, view.py) and the run record (continued from
  /// output.restart). Call once, before the first step; collective in a distributed run.
  void start(RunOutput output);

  /// Runs to the end time, or until the step `last_step` (absolute, `mpm run --steps`), or until the observer
  /// stops or interrupts it; then checks the materials' state, writes the checkpoint of the end (when the end time
  /// was reached) and the last frame. Throws StabilityError (after writing the last good state) when the guard or
  /// the energy sentinel stops it.
  RunEnd run(std::optional<Index> last_step = {}, RunObserver<Dim>* observer = nullptr);
  /// One step toward the end time (landing on it); past the end time, a step of the stable size. The step that
  /// reaches the end time ends the run as run() does.
  RunEnd step(RunObserver<Dim>* observer = nullptr);
  /// Steps until the time `t` (s), the last step landing on it.
  RunEnd advance_to(Real t, RunObserver<Dim>* observer = nullptr);

  /// Writes a frame of the current state now: to the run's directory, or (another `directory`) to a series of
  /// its own there (a writer per directory, with the run's fields, prefix and view.py).
  void write_frame(const std::filesystem::path& directory);
  /// Records that particle data was changed from outside the step (the Python package's writable views); the next
  /// step, or apply_particle_changes(), calls Simulation::particles_changed().
  void mark_particles_changed() { changed_ = true; }
  void apply_particle_changes();

  Simulation<Dim>& simulation() { return *sim_; }
  const Simulation<Dim>& simulation() const { return *sim_; }
  /// The output directory, or empty when the run writes none.
  std::filesystem::path output_directory() const;
  const RunRecord& record() const { return record_; }
  /// Every warning logged, in order: the built scene's, then those found while stepping (and those of the run a
  /// restart continues).
  std::vector<std::string> warnings() const;
  /// The histories' writer (their columns and, with RunOutput::keep_history_rows, every row so far), or null when
  /// the run has none or neither writes nor keeps them.
  const HistoryWriter<Dim>* histories() const { return histories_.get(); }
  /// The last checkpoint written by this process, or none.
  const std::optional<std::filesystem::path>& last_checkpoint() const { return last_checkpoint_; }
  /// Wall time spent in run()'s steps (their output and checks included, the end's writes not), s.
  double stepping_seconds() const { return stepping_seconds_; }

 private:
  enum class Next { go_on, stop, interrupt };
  /// Everything after a step: the step log, the frames and histories due, the energy and state checks, the
  /// checkpoint due, then the observer; applies the views' changes for the next step.
  Next after_step(RunObserver<Dim>* observer);
  /// Runs `steps` with the step flags asked and the output of a stop by the guard written.
  template <class Steps>
  void stepping(RunObserver<Dim>* observer, Steps&& steps);
  /// The end of a stepping call: a checkpoint on interruption, the end's checks and checkpoint, the last frame.
  RunEnd conclude(Next next, bool was_finished, bool always);
  void write(bool always);
  void check_state();
  void check_energy();
  void check_outflow();
  void write_checkpoint();
  void warn(std::string message);
  std::unique_ptr<OutputWriter<Dim>> make_writer(const std::filesystem::path& directory) const;

  const SceneDescription scene_;
  std::unique_ptr<Simulation<Dim>> sim_;
  RunLog& log_;
  std::vector<std::string> scene_warnings_;
  std::optional<GravityStageReport> gravity_stage_;
  std::vector<BuiltHistory<Dim>> built_histories_;  ///< until start()
  RunOutput output_;
  std::unique_ptr<OutputWriter<Dim>> writer_;
  std::unique_ptr<HistoryWriter<Dim>> histories_;
  std::unique_ptr<io::CsvLog> step_log_;
  std::map<std::string, std::unique_ptr<OutputWriter<Dim>>> frames_;  ///< write_frame() elsewhere, by directory
  RunRecord record_;
  std::optional<std::filesystem::path> last_checkpoint_;
  Index last_checkpoint_step_ = -1;
  double stepping_seconds_ = 0;
  bool started_ = false;  ///< the first stepping call wrote the first frame
  bool changed_ = false;  ///< particle data changed through views since the last step
};

}  // namespace mpm
