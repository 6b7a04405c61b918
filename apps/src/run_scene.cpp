#include "mpm/app/run_scene.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string_view>

#include "mpm/app/body_summary.hpp"
#include "mpm/app/memory_budget.hpp"
#include "mpm/app/memory_estimate.hpp"
#include "mpm/app/plausibility.hpp"
#include "mpm/app/rank_report.hpp"
#include "mpm/app/run_checkpoints.hpp"
#include "mpm/app/run_console.hpp"
#include "mpm/app/run_description.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/app/step_estimate.hpp"
#include "mpm/app/stop_signals.hpp"
#include "mpm/core/units.hpp"
#include "mpm/diagnostics/energy_sentinel.hpp"
#include "mpm/failure/failure_module.hpp"
#include "mpm/history/history_kind.hpp"
#include "mpm/run/run.hpp"

namespace mpm::app {
namespace {

/// The scene as the command line changes it (`-o`, `--end-time`): modules writing their own files (contact
/// forces) follow -o too. Throws std::invalid_argument for `--steps` < 1 or an end time that is not positive.
SceneDescription scene_for(const SceneDescription& scene_in, const RunOptions& options) {
  SceneDescription scene = scene_in;
  if (options.output_directory) scene.output.directory = options.output_directory->string();
  if (options.steps && *options.steps < 1)
    throw std::invalid_argument(fmt::format("--steps must be at least 1, not {}", *options.steps));
  if (options.end_time) {
    if (!(*options.end_time > 0) || !std::isfinite(*options.end_time))
      throw std::invalid_argument(
          fmt::format("--end-time must be a positive number of seconds, not {}", *options.end_time));
    scene.solver.end_time = *options.end_time;
  }
  return scene;
}

/// Continues `point` (restart_point of run_checkpoints.hpp) on `sim`: says what it continues and what a fork
/// changed; a checkpoint that does not fit the built simulation is a RestartError.
template <int Dim>
void restore_simulation(Simulation<Dim>& sim, const RestartPoint& point, std::ostream& log) {
  std::vector<std::string> notes;
  try {
    notes = sim.restore_state(point.archive);
  } catch (const ArchiveError& e) {
    throw RestartError(fmt::format("{}: does not fit the scene: {}", point.file.string(), e.what()));
  }
  fmt::print(log, "restart: continuing {} at step {} (t = {:.9g} s)\n", point.file.string(), sim.step(), sim.time());
  for (const auto& d : point.changes)
    fmt::print(log, "fork: {}:{}: {}: {} in the checkpoint, {} now\n", d.where.file, d.where.line, d.key, d.was, d.now);
  for (const auto& n : notes) fmt::print(log, "note: {}\n", n);
}

template <int Dim>
void check(const SceneDescription& scene, std::ostream& out, std::ostream& log, int ranks) {
  auto sim = build_simulation<Dim>(scene, /*gravity_stage=*/false);  // a check does not run the stage
  std::vector<std::string> warnings;
  build_histories<Dim>(scene, *sim, warnings);  // what only the built bodies can refuse
  for (const auto& w : warnings) fmt::print(log, "warning: {}\n", w);
  if (const std::string w = step_warning(estimate_steps<Dim>(scene, *sim)); !w.empty())
    fmt::print(log, "warning: {}\n", w);
  for (const auto& w : plausibility_warnings<Dim>(scene, *sim)) fmt::print(log, "warning: {}\n", w);
  const Real dt = sim->next_time_step();
  fmt::print(out,
             "{}: valid. {}D{}, {} particles in {} {}, {} nodes; {} with {} functions; dt = {:.6g} s "
             "(stable bound {:.6g} s, {}); about {} steps to t = {:.6g} s{}\n",
             scene.file, Dim,
             scene.grid.coordinates == Coordinates::axisymmetric
                 ? " axisymmetric (x = r, y = z; masses, energies and forces per full revolution)"
                 : "",
             sim->particle_count(), sim->bodies().size(), sim->bodies().size() == 1 ? "body" : "bodies",
             sim->grid().size(), scene.solver.scheme_name(), scene.solver.shape_function, dt, sim->stable_time_step(),
             sim->time_step_limiter(), static_cast<long long>(std::ceil(scene.solver.end_time / dt)),
             scene.solver.end_time, scene.solver.dt ? "" : " at this first dt (the adaptive step follows the run)");
  if (scene.units != units::unit_systems().front().name)
    fmt::print(out, "units: the scene's numbers are in {} ({}); every value above and every output is SI\n",
               scene.units, units::find_unit_system(scene.units)->derived);
  fmt::print(out, "{}{}", body_summary<Dim>(*sim), set_summary<Dim>(*sim, scene));
  const MemoryEstimate memory = estimate_memory<Dim>(scene, sim->grid().geometry, true);
  const MemoryBudget budget = available_memory();
  fmt::print(out, "memory: about {} estimated before building ({:.4g} particles, {} grid nodes), {} available ({})\n",
             format_bytes(memory.bytes()), memory.particles(), memory.nodes, format_bytes(budget.bytes), budget.source);
  if (ranks > 0) rank_report<Dim>(scene, *sim, ranks, out, log);
}

/// The command line's changes to the scene and a fork's (`fork`, nullptr for none), as "key: value" lines
/// (recorded in the output files).
std::vector<std::string> overrides(const RunOptions& options, const RestartPoint* fork) {
  std::vector<std::string> lines;
  if (fork)
    for (const auto& d : fork->changes)
      lines.push_back(fmt::format("{}: {}  # fork: {} in the checkpoint", d.key, d.now, d.was));
  if (options.output_directory) lines.push_back("output.directory: " + options.output_directory->string());
  if (options.end_time) lines.push_back(fmt::format("solver.end_time: {}", *options.end_time));
  if (options.steps) lines.push_back(fmt::format("steps: {}  # --steps", *options.steps));
  for (const auto& line : options.overrides) lines.push_back(line);
  return lines;
}

/// RankCountError (exit status 2 on every rank) for what a distributed run does not take yet; before anything is
/// written or restored.
template <int Dim>
void refuse_what_cannot_be_distributed(const SceneDescription& scene, const RunOptions& options,
                                       const Simulation<Dim>& sim) {
  const int ranks = options.communicator->size();
  if (const std::string why = sim.why_not_distributed(ranks); !why.empty())
    throw RankCountError(fmt::format("{}: {} ({} ranks)", scene.file, why, ranks));
}

/// A distributed run, before anything is written or restored: refuses what cannot be distributed yet, and lets
/// only rank 0's modules write files of their own.
template <int Dim>
void prepare_ranks(const SceneDescription& scene, const RunOptions& options, Simulation<Dim>& sim) {
  refuse_what_cannot_be_distributed(scene, options, sim);
  for (const auto& m : sim.modules()) m->set_writes_files(options.communicator->rank() == 0);
}

/// With `--restart`, the checkpoint it names restored into `sim` (after the histories joined it, before it is
/// distributed) and the checkpoints' schedule continued; nothing without.
template <int Dim>
std::optional<RestartPoint> restart_from(const SceneDescription& scene, const std::string& scene_text,
                                         const RunOptions& options, RunCheckpoints& checkpoints, Simulation<Dim>& sim,
                                         std::ostream& log) {
  if (!options.restart) return std::nullopt;
  RestartPoint point = find_restart_point(*options.restart, scene, scene_text, log);
  const double shift = rebase_gravity_potential(point, scene);
  restore_simulation(sim, point, log);
  if (shift != 0)
    fmt::print(log,
               "fork: the gravity potential jumps by {:+.6g} J at the checkpoint with the new gravity; the energy "
               "audit's E(0) is shifted by as much\n",
               shift);
  if (const int removed = checkpoints.restore(point.archive))
    fmt::print(log, "restart: removed {} later checkpoint(s) of the interrupted run from {}\n", removed,
               checkpoints.directory().string());
  return point;
}

/// After a restart's restore: the ranks share out the one-process state.
template <int Dim>
void distribute(Simulation<Dim>& sim, const RunOptions& options) {
  sim.set_rebalance_interval(options.rebalance_every);
  sim.set_exchange_every_scatter(options.exchange_every_scatter);
  sim.distribute(options.communicator);
}

/// With a module that bounds the time step (heat conduction: diffusion), which bound governs.
template <int Dim>
void note_time_step(const Simulation<Dim>& sim, std::ostream& log) {
  if (std::any_of(sim.modules().begin(), sim.modules().end(),
                  [&](const auto& m) { return std::isfinite(m->stable_time_step(sim.bodies())); }))
    fmt::print(log, "time step: {:.6g} s, stable bound {:.6g} s governed by {}\n", sim.next_time_step(),
               sim.stable_time_step(), sim.time_step_limiter());
}

/// The summary's particles (every rank's) and the largest state of one, before the first step.
template <int Dim>
RunSummary particles_of(const Simulation<Dim>& sim, Communicator* comm) {
  RunSummary summary;
  std::array<std::int64_t, 1> count{static_cast<std::int64_t>(sim.particle_count())};
  if (comm) comm->sum(count);
  summary.particles = static_cast<std::size_t>(count[0]);
  for (const auto& b : sim.bodies())
    summary.bytes_per_particle = std::max(summary.bytes_per_particle, b.particles.bytes_per_particle());
  return summary;
}

/// `--profile`: the time per phase, and in a distributed run where the ranks differ.
template <int Dim>
void print_profile(RunSummary& summary, const Simulation<Dim>& sim, Communicator* comm, std::ostream& out) {
  summary.profile = sim.profile();
  fmt::print(out,
             "profile (wall time per phase; G2P and the stress update run fused and are split by their CPU "
             "time):\n{}\n",
             format_profile(summary.profile));
  if (!comm) return;
  // Where the ranks differ: the waiting of one is the other's extra work. Every phase, then the compute (the four
  // phases of the particles and the grid: equal particle counts and unequal compute mean unequal cores), the
  // stepping total and the particles on the rank.
  const StepProfile& p = summary.profile;
  constexpr int n = step_phase_count + 3;
  std::array<double, n> most{};
  for (int k = 0; k < step_phase_count; ++k) most[k] = p[static_cast<StepPhase>(k)];
  most[step_phase_count] =
      p[StepPhase::p2g] + p[StepPhase::grid_update] + p[StepPhase::g2p] + p[StepPhase::stress_update];
  most[step_phase_count + 1] = p.stepping_seconds();
  most[n - 1] = static_cast<double>(sim.particle_count());
  std::array<double, n> least = most;
  comm->max(most);
  comm->min(least);
  for (int k = 0; k < n - 1; ++k) {
    const std::string_view name = k < step_phase_count    ? step_phase_names[k]
                                  : k == step_phase_count ? std::string_view("compute")
                                                          : std::string_view("stepping");
    fmt::print(out, "ranks' {}: min {:.4f} s, max {:.4f} s\n", name, least[k], most[k]);
  }
  fmt::print(out, "ranks' particles at the end: min {:.0f}, max {:.0f}\n", least[n - 1], most[n - 1]);
}

/// The end of a run that reached its end time or its step limit: the summary, printed to `out` (stdout: the
/// result of the command, which `mpm run SCENE > summary.txt` keeps apart from the log).
template <int Dim>
RunSummary summarise(RunSummary summary, const Run<Dim>& run, Index first_step, const RunOptions& options,
                     Communicator* comm, std::ostream& out) {
  const Simulation<Dim>& sim = run.simulation();
  summary.steps = sim.step();
  summary.warnings = run.warnings();
  summary.wall_seconds = run.stepping_seconds();
  summary.particle_updates_per_second = static_cast<double>(summary.particles) *
                                        static_cast<double>(summary.steps - first_step) /
                                        std::max(summary.wall_seconds, 1e-300);
  // What left through outflow faces and what eroded took its energy along, booked (energy.csv's outflow_* and
  // eroded_* columns; eq. 8.4): the change is that of E(t) + E_out + E_eroded.
  Real removed = sim.boundary().outflow_energy();
  for (const auto& m : sim.modules()) removed += m->removed_energy();
  const Real e0 = run.record().initial_energy, e1 = sim.energy().total() + removed;
  summary.relative_energy_change = e0 != 0 ? (e1 - e0) / std::abs(e0) : e1;
  for (const auto& line : sim.boundary().outflow_summary()) fmt::print(out, "{}\n", line);
  if (const EnergySentinel<Dim>* sentinel = sim.energy_sentinel()) {
    summary.largest_energy_ratio = sentinel->largest_ratio();
    summary.largest_energy_ratio_step = sentinel->largest_ratio_step();
    if (summary.largest_energy_ratio > 0)
      fmt::print(out, "energy sentinel: largest balance / tolerance {:.4g} (step {}), external work {:.6g} J\n",
                 summary.largest_energy_ratio, summary.largest_energy_ratio_step, sentinel->work());
    else  // the sentinel watches gains: a run that only lost energy has no largest ratio to report
      fmt::print(out, "energy sentinel: the balance E(t) - E(0) - W never rose above 0, external work {:.6g} J\n",
                 sentinel->work());
  }
  for (const auto& m : sim.modules())
    if (const auto* failure = dynamic_cast<const FailureModule<Dim>*>(m.get())) {
      std::vector<std::string> names;
      for (const auto& b : sim.bodies()) names.push_back(b.name);
      for (const std::string& line : failure->summary(names)) fmt::print(out, "{}\n", line);
    }
  fmt::print(out,
             "done: {} steps to t = {:.6g} s in {:.3f} s wall, {:.4g} particle-updates/s, {} particles ({} B state "
             "each), relative energy change {:+.3e}; output in {}\n",
             summary.steps, sim.time(), summary.wall_seconds, summary.particle_updates_per_second, summary.particles,
             summary.bytes_per_particle, summary.relative_energy_change, run.output_directory().string());
  if (options.profile) print_profile(summary, sim, comm, out);
  return summary;
}

/// The end of a run a signal stopped (after its checkpoint and last frame): how to resume it.
template <int Dim>
RunSummary stopped_by_signal(RunSummary summary, const Run<Dim>& run, const RunCheckpoints& checkpoints,
                             const SceneDescription& scene, const RunOptions& options, std::ostream& log) {
  const Simulation<Dim>& sim = run.simulation();
  summary.stopped_by_signal = StopSignals::requested();
  fmt::print(log, "stopped by {} at step {} (t = {:.9g} s); resume with: mpm run {} --restart {}{}\n",
             signal_name(summary.stopped_by_signal), sim.step(), sim.time(), scene.file,
             run.last_checkpoint() ? run.last_checkpoint()->string() : checkpoints.directory().string(),
             options.output_directory ? " -o " + options.output_directory->string() : std::string());
  summary.steps = sim.step();
  summary.warnings = run.warnings();
  return summary;
}

template <int Dim>
RunSummary run(const SceneDescription& scene_in, const RunOptions& options, std::ostream& out, std::ostream& log) {
  const SceneDescription scene = scene_for(scene_in, options);
  const StopSignals stop_signals;  // SIGINT, SIGTERM, SIGUSR1: stop after the current step
  Communicator* const comm =
      options.communicator && options.communicator->size() > 1 ? options.communicator.get() : nullptr;
  RunConsole<Dim> console(log, scene, options);  // the log, the progress line, signals, failure/
  const std::unique_ptr<Run<Dim>> job =
      make_run<Dim>(scene, console, options.restart.has_value());  // the simulation and its histories
  Simulation<Dim>& sim = job->simulation();
  if (comm) prepare_ranks(scene, options, sim);
  job->log_warnings();
  const std::filesystem::path directory = options.output_directory.value_or(scene.output.directory);
  const std::string scene_text = read_scene_text(scene);
  RunCheckpoints checkpoints(scene, scene_text, checkpoint_directory(scene, directory),
                             !comm || comm->rank() == 0);  // a distributed run's: the one-process one, by rank 0
  checkpoints.kill_in_checkpoint(options.test.kill_in_checkpoint);
  const std::optional<RestartPoint> restart = restart_from(scene, scene_text, options, checkpoints, sim, log);
  if (comm) distribute(sim, options);
  job->start({directory, run_field_data(scene, overrides(options, restart ? &*restart : nullptr)),
              view_script_for(scene), restart ? &restart->archive : nullptr, comm, &checkpoints, options.profile});
  if (restart && (!comm || comm->rank() == 0)) write_fork_changes(job->output_directory(), *restart);
  RunSummary summary = particles_of(sim, comm);
  note_time_step(sim, log);
  const Index first_step = sim.step();  // 0, or the step a restart continues
  console.begin(sim, job->output_directory());
  const RunEnd end = job->run(options.steps ? std::optional<Index>(*options.steps) : std::nullopt, &console);
  console.end_progress_line();
  if (end == RunEnd::interrupted) return stopped_by_signal(std::move(summary), *job, checkpoints, scene, options, log);
  return summarise(std::move(summary), *job, first_step, options, comm, out);
}

}  // namespace

template <int Dim>
std::unique_ptr<Run<Dim>> make_run(const SceneDescription& scene, RunLog& log, bool restarting) {
  std::optional<GravityStageReport> stage;
  if (scene.solver.gravity_stage && !restarting) stage.emplace();
  auto sim = build_simulation<Dim>(scene, !restarting, stage ? &*stage : nullptr);
  std::vector<std::string> warnings;  // a time step collapsed by a typo, implausible numbers
  if (std::string w = step_warning(estimate_steps<Dim>(scene, *sim)); !w.empty()) warnings.push_back(std::move(w));
  for (auto& w : plausibility_warnings<Dim>(scene, *sim)) warnings.push_back(std::move(w));
  if (stage && !stage->converged)  // on_no_equilibrium: warn (stop threw)
    warnings.push_back(stage->summary() + ": the run starts from the state reached, which is not at rest");
  return std::make_unique<Run<Dim>>(scene, std::move(sim), log, std::move(warnings), std::move(stage));
}

template std::unique_ptr<Run<1>> make_run<1>(const SceneDescription&, RunLog&, bool);
template std::unique_ptr<Run<2>> make_run<2>(const SceneDescription&, RunLog&, bool);
template std::unique_ptr<Run<3>> make_run<3>(const SceneDescription&, RunLog&, bool);

void check_scene(const SceneDescription& scene, std::ostream& out, std::ostream& log, int ranks) {
  switch (scene.dimension) {
    case 1:
      return check<1>(scene, out, log, ranks);
    case 2:
      return check<2>(scene, out, log, ranks);
    default:
      return check<3>(scene, out, log, ranks);
  }
}

RunSummary run_scene(const SceneDescription& scene, const RunOptions& options, std::ostream& out, std::ostream& log) {
  switch (scene.dimension) {
    case 1:
      return run<1>(scene, options, out, log);
    case 2:
      return run<2>(scene, options, out, log);
    default:
      return run<3>(scene, options, out, log);
  }
}

}  // namespace mpm::app
