#pragma once
/// \file simulation_handle.hpp
/// The run of a scene of any dimension behind one interface, for the Python bindings: the run object of the `mpm`
/// program (mpm/run/run.hpp, made by app::make_run), so that the output, the warnings, the energy sentinel's stop and
/// the checkpoints are those of `mpm run`; stepping inside a task arena of the requested number of threads. Nothing
/// here knows Python: the bindings release the interpreter lock around the stepping calls and wrap the callbacks.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mpm/particles/field_storage.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/simulation/energy.hpp"

namespace mpm::python {

/// A field's values in place, for a NumPy view.
/// The books of particles that left the run one way (SimulationHandle::removed).
struct RemovedTotals {
  std::string name;  ///< "outflow_x_min", ..., or "eroded"
  EnergyBalance energy;
  double particles = 0;
};

struct FieldArray {
  FieldStorage storage;
  std::vector<Index> shape;    ///< of the whole array (particles or nodes first)
  std::vector<Index> strides;  ///< bytes
  bool writable = false;
};

/// What run() does besides stepping.
struct RunControl {
  std::optional<Index> steps;  ///< stop after this many more steps (else at the end time)
  Index every = 1;             ///< call `callback` after the steps whose number is a multiple of this
  /// Called after every `every`-th step; returns true to stop the run after that step.
  std::function<bool()> callback;
  /// Called about every `poll_seconds` of wall time and once at the end (progress display, Ctrl-C).
  std::function<void()> poll;
  double poll_seconds = 0.25;
};

/// The grid's geometry, for the Python grid object.
struct GridInfo {
  std::vector<double> origin, cell_size;  ///< m, per axis
  std::vector<Index> nodes;               ///< per axis
};

class SimulationHandle {
 public:
  virtual ~SimulationHandle() = default;
  virtual int dimension() const = 0;

  // Stepping (Run::step, advance_to, run). Each call first applies changes made through writable views
  // (particles_changed()); the first writes the first frame of the scene's output, as `mpm run` does. Throws
  // StabilityError when the guard or the energy sentinel (`solver.on_energy_drift: stop`) stops the run.
  /// One step toward the end time (landing on it); past the end time, a step of the stable size.
  virtual void step() = 0;
  /// Steps until time t, the last step landing on t; `poll` (if set) as in RunControl, every `poll_seconds`.
  virtual void advance_to(double t, const std::function<void()>& poll, double poll_seconds) = 0;
  /// Steps to the end time (or RunControl::steps more steps, or until the callback stops it), writing the
  /// frames that are due and a last frame where it stops, like `mpm run`. Returns whether the callback stopped it.
  virtual bool run(const RunControl& control) = 0;

  virtual double time() const = 0;
  virtual Index step_count() const = 0;
  /// The size of the next step() (the stable step times the CFL factor, or the fixed dt; shortened to land on
  /// the end time), for the state as changed through the views.
  virtual double dt() = 0;
  virtual double end_time() const = 0;
  /// Whether the end time has been reached (Simulation::finished()).
  virtual bool finished() const = 0;
  virtual double stable_time_step() = 0;
  virtual Index particle_count() const = 0;
  virtual EnergyBalance energy() const = 0;
  /// What left the run since t = 0, one entry per outflow face ("outflow_y_max") and, when a material erodes,
  /// "eroded": the sums of energy.csv's outflow_F_* and eroded_* columns.
  virtual std::vector<RemovedTotals> removed() const = 0;
  /// Writes a frame of the current state to `directory` (the scene's fields and prefix; a .pvd series and
  /// energy.csv per directory, continued by later calls).
  virtual void write_frame(const std::string& directory) = 0;
  /// The output directory of the scene's output section, or empty when the simulation writes none.
  virtual std::string output_directory() const = 0;
  /// The names of the scene's histories (output.histories), in scene order; their rows are kept in memory whether
  /// or not the simulation writes files.
  virtual std::vector<std::string> history_names() const = 0;
  /// History k's columns ("time [s]", "step", then "name [unit]") and its rows so far, row after row.
  virtual std::vector<std::string> history_columns(std::size_t k) const = 0;
  virtual std::vector<double> history_rows(std::size_t k) const = 0;

  virtual std::vector<std::string> body_names() const = 0;
  virtual Index body_size(int body) const = 0;
  /// The fields of a body that field() can view: the core's, then the on-demand ones that are arrays of
  /// numbers.
  virtual std::vector<std::string> particle_fields(int body) = 0;
  /// Throws std::out_of_range for a name that particle_fields() does not list (saying why for a record field).
  virtual FieldArray particle_field(int body, const std::string& name) = 0;
  /// ParticleSet::generation() of the body: a view made when it had another value is stale.
  virtual std::uint64_t generation(int body) const = 0;
  /// The values the output writes for the named output field (output_fields.hpp), `components` per particle.
  virtual std::vector<double> output_values(int body, const std::string& name, int& components) const = 0;
  /// Records that particle data was changed through a view: the next step first calls particles_changed().
  virtual void mark_changed() = 0;

  virtual GridInfo grid_info() const = 0;
  virtual std::vector<std::string> grid_fields() const = 0;
  /// A read-only view of a nodal field, shaped (nodes_x, nodes_y, nodes_z[, components]).
  virtual FieldArray grid_field(const std::string& name) = 0;
};

/// Builds the run of `scene` (app::make_run) inside an arena of `threads` threads (0: all cores) and logs its
/// warnings to stderr. `output_directory`: the scene's output section (and its checkpoints) is written there (empty:
/// nothing is written). Throws SceneError like the program.
std::unique_ptr<SimulationHandle> make_simulation(const SceneDescription& scene, int threads,
                                                  const std::string& output_directory);

}  // namespace mpm::python
