#pragma once
/// \file simulation.hpp
/// A running simulation: grid, bodies, scheme, boundary conditions and modules, plus the time-step
/// control (review eqs 2.71-2.73) and the stability guard. Build one with build_simulation() from a
/// scene, or by hand in tests.

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/grid/active_tiles.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/parallel/tile_halo.hpp"
#include "mpm/schemes/scheme.hpp"
#include "mpm/simulation/energy.hpp"
#include "mpm/simulation/module.hpp"
#include "mpm/simulation/step_profile.hpp"

namespace mpm {

template <int Dim>
class EnergySentinel;

template <int Dim>
struct SimulationSettings {
  TransferSettings<Dim> transfer;
  std::optional<Real> fixed_dt;  ///< s; when empty the time step is cfl * stable time step
  Real cfl = 0.5;                ///< alpha_dt of eq. 2.73
  Real end_time = 0;             ///< s
  int snapshot_interval = 20;    ///< steps between snapshots kept for the stability guard
  int sort_interval = 20;        ///< steps between reorderings of the particles by cell
  /// Distributed run: steps between checks of the balance; when the most loaded rank's cost exceeds the mean by
  /// more than 10%, the tiles are dealt anew (`mpm run --rebalance-every`; 0: never).
  int rebalance_interval = 50;
  /// Distributed run: every scatter exchanges ghost nodes, not only those of bodies near a cut (TileBins::exchange;
  /// the same bits, slower: the baseline of the benchmark's pairs, docs/PERFORMANCE.md §16.4).
  bool exchange_every_scatter = false;
  /// One process: the grid kernels visit only the nodes the particles of the occupied tiles reach (active_tiles.hpp;
  /// the same bits as the dense grid, test SparseGrid.*). False: every node every step (the reference).
  bool sparse_grid = true;
};

template <int Dim>
class Simulation {
 public:
  /// `boundary`: the conditions on the grid's faces; unless it has none, it joins the step as the first module
  /// (GridBoundary), so it runs before every module added later in each phase.
  Simulation(const GridGeometry<Dim>& geometry, std::vector<Body<Dim>> bodies, std::unique_ptr<Scheme<Dim>> scheme,
             GridBoundary<Dim> boundary, const SimulationSettings<Dim>& settings);

  /// Adds a module (before the first step: its state joins the guard's first snapshot).
  void add_module(std::shared_ptr<Module<Dim>> module) {
    module->save_state(snapshot_.modules, module_prefix(*module));
    hooks_.add(std::move(module));
  }
  const std::vector<std::shared_ptr<Module<Dim>>>& modules() const { return hooks_.all(); }
  /// Takes `module` out of the step (the gravity stage's meter, gravity_stage.hpp, when the stage ends).
  void remove_module(const Module<Dim>* module) { hooks_.remove(module); }
  /// Adds the energy sentinel (energy_sentinel.hpp; the builder adds one to every scene, last) as a module and keeps
  /// it, for the run object (run/run.hpp), which logs its drift or stops on it, and the flight recorder's diagnosis.
  /// (A template only so that this header needs no definition of EnergySentinel: `Sentinel` is EnergySentinel<Dim>.)
  template <class Sentinel>
  void add_energy_sentinel(std::shared_ptr<Sentinel> sentinel) {
    energy_sentinel_ = sentinel.get();
    add_module(std::move(sentinel));
  }
  /// The energy sentinel, or null when none was added.
  const EnergySentinel<Dim>* energy_sentinel() const { return energy_sentinel_; }

  /// Makes this process one rank of a distributed run (docs/distributed.md §4): every rank built the
  /// same simulation from the scene; each keeps the particles of its tiles (a box of them), and from now on its
  /// scatters exchange ghost nodes, its particles migrate to the rank owning their tile after every step, and its time
  /// step, guard, energy() and body_energy() are reduced over the ranks, so that every result has the bits of a
  /// one-process run. Call before the first step, on every rank. A communicator of one rank changes nothing.
  /// Throws std::invalid_argument (on every rank alike) for what cannot run distributed yet: a scheme or module
  /// that has no ghost exchange, or more ranks than tiles.
  void distribute(std::shared_ptr<Communicator> comm);
  /// Empty when the run can be distributed over `ranks` ranks, else why not (what distribute() would throw).
  std::string why_not_distributed(int ranks) const;
  /// The run's other ranks, or null in one process.
  Communicator* communicator() const { return comm_.get(); }
  /// The distributed run's tile ownership and ghost-node exchange, or null.
  const TileHalo* halo() const { return halo_.get(); }
  /// Reassigns the tiles to the ranks (every rank the same `owner` of each tile, TileHalo) and migrates the
  /// particles. Results do not depend on it (the tests deal the tiles at random every step).
  void reassign_tiles(std::vector<int> owner);
  /// Bytes of ghost nodes this rank has sent (every tile assignment's), for the halo model's test.
  std::size_t halo_bytes_sent() const { return halo_bytes_before_ + (halo_ ? halo_->bytes_sent() : 0); }
  /// Distributed run: the bodies whose scatters exchange ghost nodes in the next step (TileBins::exchange): those
  /// with a particle in a tile that writes a node of several ranks at the end of the last step, or all of them when
  /// that is not known (the first step, after a restore, a roll-back or a new tile assignment).
  std::size_t exchanging_bodies() const;
  /// Steps between balance checks of a distributed run (SimulationSettings::rebalance_interval; 0: never).
  void set_rebalance_interval(int steps) { settings_.rebalance_interval = steps; }
  /// The transfers' settings from the next step on (the gravity stage's damping and PIC transfer, then the scene's).
  void set_transfer_settings(const TransferSettings<Dim>& transfer) { settings_.transfer = transfer; }
  /// Sets the clock to `time` without a step (the gravity stage runs each of its steps from -dt to 0, so that the
  /// conditions end them with their values of t = 0).
  void set_time(Real time) { time_ = time; }
  /// Starts the clock anew: time 0, step 0, the guard's snapshot taken of the present state (the gravity stage's
  /// end: the run starts from the state it reached).
  void reset_clock();
  /// Distributed run: whether every scatter exchanges (SimulationSettings::exchange_every_scatter).
  void set_exchange_every_scatter(bool on) { settings_.exchange_every_scatter = on; }
  /// One process: whether the grid kernels visit only the nodes the particles reach (SimulationSettings::sparse_grid;
  /// the same bits either way). From the next step.
  void use_sparse_grid(bool on) {
    settings_.sparse_grid = on;
    active_tiles_.forget();
  }
  /// Flags of the caller that every rank must agree on after a step (the run loop: a checkpoint is due, a stop signal
  /// arrived): `flags(step, time)` is asked at the end of each step (its number and the time it reached), before the
  /// step's reduction, and step_flags() is then the bitwise OR over the ranks of its lowest `step_flag_bits` bits. They
  /// travel in the step's one reduction with the wave speed, the guard's flag and the migration's (docs/distributed.md
  /// §5.4). An empty function: no flags.
  static constexpr int step_flag_bits = 4;
  void set_step_flags(std::function<unsigned(Index step, Real time)> flags) { step_flags_fn_ = std::move(flags); }
  unsigned step_flags() const { return step_flags_; }
  /// The occupied tiles of the last step and the nodes the grid kernels visited (one process, sparse_grid).
  const ActiveTiles& active_tiles() const { return active_tiles_; }
  /// The owner of each tile that balances the particles of all ranks: boxes of tiles by recursive bisection
  /// (bisect_tiles; a collective call).
  std::vector<int> balanced_owners() const;
  /// The tiles of the scatter as a distributed run owns them (the grid and the shape function's slab and reach).
  TileGrid tile_grid() const;
  /// The cost of every tile (tile_cost: its particles, on all ranks in a distributed run, where this is a collective
  /// call, plus a tenth of its cells).
  std::vector<double> tile_costs() const;

  /// Largest stable time step of the current state (eq. 2.73 with alpha_dt = 1), of the viscous
  /// materials (h^2 / (2 Dim nu)) and of the modules.
  Real stable_time_step() const;
  /// Which bound governs stable_time_step(): the CFL bound (eq. 2.73), the viscous one or a module's
  /// time_step_bound().
  std::string time_step_limiter() const;
  /// The time step the next step will take: the fixed dt, or cfl * stable_time_step().
  Real next_time_step() const;
  /// Takes one step of size dt. If the stability guard trips, the state is rolled back to the end of
  /// the previous step (the last good state) and StabilityError is thrown.
  void advance(Real dt);
  /// The flight recorder's replay (docs/theory.md §7), after advance() threw StabilityError: restores the
  /// snapshot the guard rolled back to and retakes every step from it through the failing one, calling
  /// `after_step` on the snapshot's state and after each step; the failing step is taken without the guard, so the last
  /// call sees the state the guard rejected, and the simulation is left in it. Returns false (and does nothing) when no
  /// step failed.
  bool replay_failure(const std::function<void(const Simulation&)>& after_step);
  /// The step of the snapshot replay_failure() starts from (valid after a failure).
  Index failure_replay_start() const { return failure_ ? failure_->step : 0; }
  /// Advances until end_time, or until step() reaches `last_step` when one is given (`mpm run --steps`);
  /// `after_step` is called after every step (for output and progress).
  void run(const std::function<void(const Simulation&)>& after_step = {}, std::optional<Index> last_step = {});
  /// reached(end_time).
  bool finished() const;
  /// Call after changing particle data between steps from outside the step (the Python package's writable
  /// views): the time-step bound is recomputed from the changed state and the stability guard's snapshot is
  /// taken again, so that a roll-back restores the changed state rather than the one before the change.
  void particles_changed();
  /// Whether time() has reached `target_time` (a step that lands within a millionth of a step of it counts).
  bool reached(Real target_time) const;
  /// The size of the next step toward `target_time`: next_time_step(), shortened to land on target_time
  /// (run() steps toward end_time with it).
  Real time_step_toward(Real target_time) const;

  Real time() const { return time_; }
  Index step() const { return step_; }
  const SimulationSettings<Dim>& settings() const { return settings_; }
  const Grid<Dim>& grid() const { return grid_; }
  const std::vector<Body<Dim>>& bodies() const { return bodies_; }
  std::vector<Body<Dim>>& bodies() { return bodies_; }
  const Scheme<Dim>& scheme() const { return *scheme_; }
  /// The particles of this process (of this rank in a distributed run).
  Index particle_count() const;
  /// The conservation audit of all bodies; in a distributed run a collective call whose result, the same on every
  /// rank, has the bits of the one-process audit.
  EnergyBalance energy() const;
  /// The audit of one body (energy() is the sum over the bodies, accumulated in the same order).
  EnergyBalance body_energy(const Body<Dim>& body) const;
  /// The conditions on the grid's faces (velocity constraints, tractions, outflow with its books and notices).
  const GridBoundary<Dim>& boundary() const { return *boundary_; }

  /// Saves the whole state of the run (simulation_state.cpp): time, step, the time-step control, every
  /// particle field of every body in id order with the order the particles are stored in, and the modules'
  /// state. What a checkpoint holds of the simulation.
  void save_state(StateArchive& archive) const;
  /// Whether this rank owns node `n` (a distributed run: every node has one owner, whose copy holds the one-process
  /// values; sums and gathers over nodes take owned ones); one process: every node.
  bool owns_node(Index n) const { return !halo_ || halo_->owns_node(n); }
  /// Every body with every rank's particles, on rank 0 of a distributed run, in the one-process storage order (the
  /// order of a checkpoint and of a one-process run's frames), without the grid-side members (bins, own grid);
  /// nothing on the other ranks. A collective call; in one process, copies of the bodies.
  std::vector<Body<Dim>> gather_bodies() const;
  /// Continues from a saved state, on a simulation built from the same scene (the same bodies with as many
  /// particles, or fewer when an outflow face removed some: the saved ones by id, the same modules); the guard's
  /// snapshot is taken there. Returns notes on fields that only one
  /// side has (a fork that changed the output fields); throws ArchiveError for anything else that differs.
  std::vector<std::string> restore_state(const StateArchive& archive);

  /// Times the phases of every following step (step_profile.hpp). Off by default: the kernels then read
  /// no clock.
  void enable_profiling(bool on = true) { profiling_ = on; }
  /// The phases timed since profiling was enabled (all zero when it never was).
  const StepProfile& profile() const { return profile_; }
  /// Adds time spent outside the steps (output) to the profile, when profiling.
  void add_to_profile(StepPhase phase, double seconds) {
    if (profiling_) profile_.add(phase, seconds);
  }

 private:
  struct Snapshot {
    std::vector<ParticleSet<Dim>> particles;
    Real time = 0;
    Index step = 0;
    WaveSpeedBound<Dim> wave_speed;
    std::vector<Real> dts_since;  ///< time steps taken after the snapshot, to replay them exactly
    StateArchive modules;         ///< the modules' state (Module::save_state)
    std::vector<int> tile_owner;  ///< distributed run: the tiles' owners then (TileHalo)
  };
  /// One step; with `guard` false a tripped guard is ignored (replay_failure()'s last step).
  void take_step(Real dt, bool guard = true);
  void take_snapshot();
  StabilityReport diagnose(Real dt) const;
  void roll_back_to_previous_step();
  /// Distributed run: sends every particle outside this rank's tiles to their owner and takes in what the others
  /// send, keeping the storage ordered by the scatter key (simulation_distributed.cpp).
  /// Returns whether a particle left or arrived on this rank (the all-to-all is collective, the answer is not: a
  /// caller that needs every rank's takes the `any`; the step's migration does not, saving a reduction per step).
  bool migrate();
  /// Distributed run, after a step: whether a particle of this rank now lies in another rank's tile (migrate() would
  /// send it; false for schemes whose particles never migrate), and per body (near_cut, 1 or 0) whether one of its
  /// particles here sits in a tile that writes a node several ranks hold or leaves this rank. One pass.
  bool scan_particles(std::span<double> near_cut) const;
  /// Distributed run: whether this rank owns the tile of a particle at x.
  bool keeps(const VecU<Dim>& x) const;
  /// Distributed run: deals the tiles anew when the most loaded rank exceeds the mean by more than 10%.
  void rebalance();
  /// Distributed run: the halo of the tile assignment `owner` (a restored snapshot's), without migrating.
  void use_owners(const std::vector<int>& owner);
  /// Distributed run: the failing particle's report, from the lowest rank that found one.
  void share_report(StabilityReport& report) const;
  /// The step context's view of the distribution (a distributed run) or of the occupied tiles (one process).
  void attach(StepContext<Dim>& ctx);

  Grid<Dim> grid_;
  std::vector<Body<Dim>> bodies_;
  std::unique_ptr<Scheme<Dim>> scheme_;
  std::shared_ptr<GridBoundary<Dim>> boundary_;  ///< never null; in hooks_ unless empty
  SimulationSettings<Dim> settings_;
  ModuleHooks<Dim> hooks_;
  WaveSpeedBound<Dim> wave_speed_;
  Real kinematic_viscosity_ = 0;  ///< largest of the materials' (viscous time-step bound)
  Real time_ = 0;
  Index step_ = 0;
  Snapshot snapshot_;
  /// The snapshot before the failing step and the steps from it through that step (dts_since), kept when the
  /// guard trips (only then: a copy of the particles), for replay_failure().
  std::unique_ptr<Snapshot> failure_;
  bool profiling_ = false;
  StepProfile profile_;
  CellSortBuffers sort_buffers_;        ///< order_by_cell's arrays, kept between the periodic sorts
  std::shared_ptr<Communicator> comm_;  ///< null in one process
  std::unique_ptr<TileHalo> halo_;
  ActiveTiles active_tiles_;
  std::function<unsigned(Index, Real)> step_flags_fn_;
  const EnergySentinel<Dim>* energy_sentinel_ = nullptr;  ///< one of the modules
  unsigned step_flags_ = 0;            ///< one process, sparse_grid: the occupied tiles of the last step
  std::size_t halo_bytes_before_ = 0;  ///< sent by the halos of earlier tile assignments
  /// Distributed run: per body, whether its particles reached a tile that writes shared nodes at the end of the last
  /// step (every rank's, from the step's reduction); valid only while near_cut_known_ (TileBins::exchange).
  std::vector<std::uint8_t> near_cut_;
  bool near_cut_known_ = false;
};

/// The wave-speed bound of every rank's particles (a distributed run): max over ranks, exact.
template <int Dim>
void reduce_wave_speed(WaveSpeedBound<Dim>& bound, Communicator& comm) {
  std::array<double, Dim + 1> v{};
  for (int d = 0; d < Dim; ++d) v[d] = bound.max_speed[d];
  v[Dim] = bound.finite ? 0 : 1;
  comm.max(v);
  for (int d = 0; d < Dim; ++d) bound.max_speed[d] = v[d];
  bound.finite = v[Dim] == 0;
}

/// The particle field a distributed run keeps its storage ordered by: the scatter key (tile_binning.hpp) of the last
/// sort, or the particle's place in the initial storage before the first.
inline constexpr std::string_view scatter_key_field = "scatter_key";

}  // namespace mpm
