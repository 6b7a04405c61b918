#include "mpm/app/run_scene.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string_view>

#include "mpm/app/flight_recorder.hpp"
#include "mpm/app/memory_estimate.hpp"
#include "mpm/app/rank_report.hpp"
#include "mpm/app/run_checkpoints.hpp"
#include "mpm/app/run_description.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/app/step_estimate.hpp"
#include "mpm/app/stop_signals.hpp"
#include "mpm/energy_sentinel.hpp"
#include "mpm/history/history_writer.hpp"
#include "mpm/memory_budget.hpp"
#include "mpm/output_writer.hpp"

namespace mpm::app {
namespace {

using Clock = std::chrono::steady_clock;

/// Thrown after a step when a signal asked the run to stop.
struct StopRequested {};

/// What the run loop carries besides the simulation and the output, saved in checkpoints.
struct RunRecord {
  double initial_energy = 0;  ///< J, for the relative energy change of the summary
  std::vector<bool> warned;   ///< per body: its material's state warning was logged
  std::vector<std::string> warnings;

  void save(StateArchive& archive) const {
    archive.put_number("run/initial_energy", initial_energy);
    const std::vector<std::int8_t> flags(warned.begin(), warned.end());
    archive.put_values<std::int8_t>("run/warned", flags);
    std::string text;
    for (const auto& w : warnings) text += w + '\n';
    archive.put_text("run/warnings", text);
  }
  void restore(const StateArchive& archive) {
    initial_energy = archive.number("run/initial_energy");
    const auto flags = archive.values<std::int8_t>("run/warned");
    if (flags.size() == warned.size()) warned.assign(flags.begin(), flags.end());
    const std::string text = archive.text("run/warnings");
    for (std::size_t begin = 0, end; (end = text.find('\n', begin)) != std::string::npos; begin = end + 1)
      warnings.push_back(text.substr(begin, end - begin));
  }
};

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
void check(const SceneDescription& scene, std::ostream& out, int ranks) {
  auto sim = build_simulation<Dim>(scene);
  std::vector<std::string> warnings;
  build_histories<Dim>(scene, *sim, warnings);  // what only the built bodies can refuse
  for (const auto& w : warnings) fmt::print(out, "warning: {}\n", w);
  if (const std::string w = step_warning(estimate_steps<Dim>(scene, *sim)); !w.empty())
    fmt::print(out, "warning: {}\n", w);
  const Real dt = sim->next_time_step();
  fmt::print(out,
             "{}: valid. {}D{}, {} particles in {} bodies, {} nodes; {} with {} functions; dt = {:.6g} s "
             "(stable bound {:.6g} s, {}); about {} steps to t = {:.6g} s\n",
             scene.file, Dim,
             scene.grid.coordinates == Coordinates::axisymmetric
                 ? " axisymmetric (x = r, y = z; masses, energies and forces per full revolution)"
                 : "",
             sim->particle_count(), sim->bodies().size(), sim->grid().size(), scene.solver.scheme_name(),
             scene.solver.shape_function, dt, sim->stable_time_step(), sim->time_step_limiter(),
             static_cast<long long>(std::ceil(scene.solver.end_time / dt)), scene.solver.end_time);
  const MemoryEstimate memory = estimate_memory<Dim>(scene, sim->grid().geometry, true);
  const MemoryBudget budget = available_memory();
  fmt::print(out, "memory: about {} estimated before building ({:.4g} particles, {} grid nodes), {} available ({})\n",
             format_bytes(memory.bytes()), memory.particles(), memory.nodes, format_bytes(budget.bytes), budget.source);
  if (ranks > 0) rank_report<Dim>(scene, *sim, ranks, out);
}

/// The command that runs `scene` as `options` did (for the flight recorder's diagnosis).
std::string run_command(const SceneDescription& scene, const RunOptions& options) {
  std::string command = "mpm run " + scene.file;
  if (options.output_directory) command += " -o " + options.output_directory->string();
  if (options.end_time) command += fmt::format(" --end-time {}", *options.end_time);
  if (options.steps) command += fmt::format(" --steps {}", *options.steps);
  if (options.restart) command += " --restart " + options.restart->string();
  for (const auto& line : options.overrides) command += "  # with " + line;
  return command;
}

/// After the guard stopped the run: the flight recorder's failure/ (flight_recorder.hpp). A failure to write it
/// is logged; the run still ends with the guard's error.
template <int Dim>
void record_flight(Simulation<Dim>& sim, const StabilityReport& report, const EnergySentinel<Dim>* sentinel,
                   const SceneDescription& scene, const RunOptions& options, const std::filesystem::path& directory,
                   std::ostream& log) {
  try {
    const FlightRecord r = record_failure(sim, report, sentinel ? sentinel->context() : HintContext{}, directory,
                                          scene.output.fields, run_command(scene, options));
    fmt::print(log, "flight recorder: {} (steps {} to {}, {} frames; diagnosis.txt)\n", r.directory.string(),
               r.first_step, report.step, r.frames);
  } catch (const std::exception& e) {
    fmt::print(log, "flight recorder: failure/ not written: {}\n", e.what());
  }
}

/// The command line's changes to the scene, as "key: value" lines (recorded in the output files).
std::vector<std::string> overrides(const RunOptions& options) {
  std::vector<std::string> lines;
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

template <int Dim>
RunSummary run(const SceneDescription& scene_in, const RunOptions& options, std::ostream& log) {
  SceneDescription scene = scene_in;  // modules writing their own files (contact forces) follow -o too
  if (options.output_directory) scene.output.directory = options.output_directory->string();
  if (options.steps && *options.steps < 1)
    throw std::invalid_argument(fmt::format("--steps must be at least 1, not {}", *options.steps));
  if (options.end_time) {
    if (!(*options.end_time > 0) || !std::isfinite(*options.end_time))
      throw std::invalid_argument(
          fmt::format("--end-time must be a positive number of seconds, not {}", *options.end_time));
    scene.solver.end_time = *options.end_time;
  }
  const StopSignals stop_signals;  // SIGINT, SIGTERM, SIGUSR1: stop after the current step
  auto sim = build_simulation<Dim>(scene);
  Communicator* const comm =
      options.communicator && options.communicator->size() > 1 ? options.communicator.get() : nullptr;
  RunSummary summary;
  // output.histories (their modules join the run; built before distribute(): the checks at t = 0 see every particle)
  auto built_histories = build_histories<Dim>(scene, *sim, summary.warnings);
  if (comm) {
    refuse_what_cannot_be_distributed(scene, options, *sim);
    for (const auto& m : sim->modules()) m->set_writes_files(comm->rank() == 0);  // before a restart's restore
  }
  if (std::string w = step_warning(estimate_steps<Dim>(scene, *sim)); !w.empty())
    summary.warnings.insert(summary.warnings.begin(), std::move(w));  // a time step collapsed by a typo
  for (const auto& w : summary.warnings) fmt::print(log, "warning: {}\n", w);
  const auto& o = scene.output;
  const std::filesystem::path directory = options.output_directory.value_or(o.directory);
  const std::string scene_text = read_scene_text(scene);
  RunCheckpoints checkpoints(
      scene, scene_text,
      o.checkpoint.directory.empty() ? directory / "checkpoints" : std::filesystem::path(o.checkpoint.directory),
      !comm || comm->rank() == 0);  // a distributed run's checkpoint: the one-process one, written by rank 0
  std::optional<RestartPoint> restart;
  if (options.restart) {
    restart = find_restart_point(*options.restart, scene, scene_text, log);
    restore_simulation(*sim, *restart, log);
    if (const int removed = checkpoints.restore(restart->archive))
      fmt::print(log, "restart: removed {} later checkpoint(s) of the interrupted run from {}\n", removed,
                 checkpoints.directory().string());
  }
  if (comm) {  // after a restart's restore: the restored one-process state is what the ranks share out
    sim->set_rebalance_interval(options.rebalance_every);
    sim->distribute(options.communicator);
  }
  OutputWriter<Dim> writer(directory, o.prefix, o.fields, o.grid, o.interval, restart ? &restart->archive : nullptr,
                           comm);  // a distributed run: a piece per rank and a .pvtu per frame
  HistoryWriter<Dim> histories(writer.directory(), std::move(built_histories), restart ? &restart->archive : nullptr,
                               !comm || comm->rank() == 0);  // every rank samples (collective sums), rank 0 writes
  writer.set_field_data(run_field_data(scene, overrides(options)));  // self-describing files
  // The scheme's own per-step table (the implicit scheme's solver.csv), one row per step. A restart starts it anew.
  std::unique_ptr<io::CsvLog> step_log;
  if (const std::string_view file = sim->scheme().step_log_file(); !file.empty())
    step_log = std::make_unique<io::CsvLog>(writer.directory() / std::string(file), sim->scheme().step_log_columns());
  if (!comm || comm->rank() == 0) io::write_view_script(writer.directory() / "view.py", view_script_for(scene));
  summary.particles = static_cast<std::size_t>(sim->particle_count());
  if (comm) {  // every rank's
    std::array<std::int64_t, 1> count{static_cast<std::int64_t>(summary.particles)};
    comm->sum(count);
    summary.particles = static_cast<std::size_t>(count[0]);
  }
  for (const auto& b : sim->bodies())
    summary.bytes_per_particle = std::max(summary.bytes_per_particle, b.particles.bytes_per_particle());
  RunRecord record;
  record.warned.assign(sim->bodies().size(), false);
  record.initial_energy = sim->energy().total();
  if (restart) record.restore(restart->archive);
  const Real e0 = record.initial_energy;
  // With a module that bounds the time step (heat conduction: diffusion), say which bound governs.
  if (std::any_of(sim->modules().begin(), sim->modules().end(),
                  [&](const auto& m) { return std::isfinite(m->stable_time_step(sim->bodies())); }))
    fmt::print(log, "time step: {:.6g} s, stable bound {:.6g} s governed by {}\n", sim->next_time_step(),
               sim->stable_time_step(), sim->time_step_limiter());
  if (options.profile) sim->enable_profiling();
  // Output is timed only when profiling (the profile's "output" phase).
  auto write = [&](const Simulation<Dim>& s, bool always) {
    const auto t0 = options.profile ? Clock::now() : Clock::time_point{};
    if (always) {
      writer.write(s);
      histories.write(s);
    } else {
      writer.write_if_due(s);
      histories.write_if_due(s);
    }
    if (options.profile) sim->add_to_profile(StepPhase::output, StepProfile::since(t0));
  };
  if (!restart) write(*sim, false);

  // The materials' validity checks (e.g. the density tolerance of a weakly compressible fluid), every
  // 50 steps and at the end; the first warning of each body is logged once.
  auto check_state = [&](const Simulation<Dim>& s) {
    for (std::size_t b = 0; b < s.bodies().size(); ++b) {
      if (record.warned[b]) continue;
      const auto& body = s.bodies()[b];
      const std::string message = body.material->state_warning(body.particles);
      if (message.empty()) continue;
      record.warned[b] = true;
      record.warnings.push_back(fmt::format("body {} at t = {:.6g} s: {}", body.name, s.time(), message));
      if (options.progress) log << '\n';
      fmt::print(log, "warning: {}\n", record.warnings.back());
    }
  };
  // A checkpoint of the state after the current step (at most one per step).
  std::optional<std::filesystem::path> last_checkpoint;
  Index last_checkpoint_step = restart ? sim->step() : -1;
  auto write_checkpoint = [&](const Simulation<Dim>& s) {
    if (s.step() == last_checkpoint_step) return;
    const auto t0 = Clock::now();
    StateArchive archive;
    s.save_state(archive);
    writer.save_state(archive);
    histories.save_state(archive);
    record.save(archive);
    last_checkpoint = checkpoints.write(archive, s.step(), s.time());
    last_checkpoint_step = s.step();
    if (last_checkpoint->empty()) return;  // a distributed run's other ranks (rank 0 writes it)
    if (options.progress) log << '\n';
    fmt::print(log, "checkpoint: {} (step {}, t = {:.9g} s; {:.3g} MB in {:.3g} s)\n", last_checkpoint->string(),
               s.step(), s.time(), 1e-6 * static_cast<double>(std::filesystem::file_size(*last_checkpoint)),
               std::chrono::duration<double>(Clock::now() - t0).count());
  };

  // The energy sentinel (energy_sentinel.hpp): its warning on the step it finds the drift, once.
  const EnergySentinel<Dim>* sentinel = nullptr;
  for (const auto& m : sim->modules())
    if (const auto* s = dynamic_cast<const EnergySentinel<Dim>*>(m.get())) sentinel = s;
  auto check_energy = [&](const Simulation<Dim>& s) {
    if (!sentinel || !sentinel->drift() || sentinel->drift()->step != s.step()) return;
    const std::string message = sentinel->drift()->message();
    if (options.progress) log << '\n';
    if (sentinel->action() == EnergyDriftAction::stop) {
      StabilityReport report;
      report.step = s.step();
      report.time = s.time();
      report.field = "energy_balance";
      report.detail = message + " (solver.on_energy_drift: stop)";
      throw StabilityError(report);
    }
    record.warnings.push_back(message);
    fmt::print(log, "warning: {}\n", message);
  };

  constexpr unsigned checkpoint_due = 1, stop_requested = 2;  // Simulation::step_flags
  const auto start = Clock::now();
  const Index first_step = sim->step();  // 0, or the step a restart continues
  auto last_print = start;
  auto after_step = [&](const Simulation<Dim>& s) {
    if (step_log) step_log->append(s.scheme().step_log_row());
    write(s, false);
    check_energy(s);
    if (s.step() % 50 == 0) check_state(s);
    // A wall-clock checkpoint interval expires, and a signal arrives, at different steps on the ranks: all write
    // when any is due and all stop after the step where any one received a signal. Both flags were asked at the end
    // of the step (step_flags below) and merged over the ranks in the step's own reduction.
    debug_fail_at_step(comm ? comm->rank() : 0, s.step());
    if (s.step_flags() & checkpoint_due) write_checkpoint(s);
    if (s.step_flags() & stop_requested) throw StopRequested{};
    if (!options.progress) return;
    const auto now = Clock::now();
    if (now - last_print < std::chrono::milliseconds(500)) return;
    last_print = now;
    const double wall = std::chrono::duration<double>(now - start).count();
    const double rate = static_cast<double>(s.particle_count()) * (s.step() - first_step) / wall;
    double eta = wall * (s.settings().end_time - s.time()) / std::max(s.time(), 1e-300);
    if (options.steps)
      eta = std::min(eta, wall * static_cast<double>(*options.steps - s.step()) / (s.step() - first_step));
    fmt::print(log, "\rstep {:>8}  t = {:<12.6g} s  {:9.3g} particle-updates/s  ETA {:7.1f} s ", s.step(), s.time(),
               rate, eta);
    log.flush();
  };
  try {
    sim->set_step_flags([&](Index step, Real time) {
      debug_raise_at_step(step);  // the tests' signal "during" this step
      return (checkpoints.due(time) ? checkpoint_due : 0u) | (StopSignals::requested() != 0 ? stop_requested : 0u);
    });
    struct Unset {  // the replays of the flight recorder and the last frame's writes ask no flags
      Simulation<Dim>& sim;
      ~Unset() { sim.set_step_flags({}); }
    } unset{*sim};
    sim->run(after_step, options.steps ? std::optional<Index>(*options.steps) : std::nullopt);
  } catch (const StabilityError& e) {
    writer.write(*sim);  // the simulation was rolled back to the last good step
    histories.write(*sim);
    if (options.progress) log << '\n';
    if (e.report().particle >= 0)  // a distributed run: every rank replays (collective steps), rank 0 writes
      record_flight(*sim, e.report(), sentinel, scene, options, writer.directory(), log);
    throw;
  } catch (const StopRequested&) {
    // The checkpoint first, then the last frame: a restart replaces that frame (it is after the checkpoint).
    write_checkpoint(*sim);
    writer.write(*sim);
    histories.write(*sim);
    summary.stopped_by_signal = StopSignals::requested();
    fmt::print(log, "stopped by {} at step {} (t = {:.9g} s); resume with: mpm run {} --restart {}{}\n",
               signal_name(summary.stopped_by_signal), sim->step(), sim->time(), scene.file,
               last_checkpoint ? last_checkpoint->string() : checkpoints.directory().string(),
               options.output_directory ? " -o " + options.output_directory->string() : std::string());
    summary.steps = sim->step();
    summary.warnings.insert(summary.warnings.end(), record.warnings.begin(), record.warnings.end());
    return summary;
  }
  summary.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();  // stepping only
  check_state(*sim);
  if (checkpoints.enabled() && sim->finished()) write_checkpoint(*sim);  // a fork may continue past the end
  write(*sim, true);
  summary.warnings.insert(summary.warnings.end(), record.warnings.begin(), record.warnings.end());
  if (options.progress) log << '\n';
  summary.steps = sim->step();
  summary.particle_updates_per_second =
      static_cast<double>(summary.particles) * (summary.steps - first_step) / std::max(summary.wall_seconds, 1e-300);
  const Real e1 = sim->energy().total();
  summary.relative_energy_change = e0 != 0 ? (e1 - e0) / std::abs(e0) : e1;
  if (sentinel) {
    summary.largest_energy_ratio = sentinel->largest_ratio();
    summary.largest_energy_ratio_step = sentinel->largest_ratio_step();
    fmt::print(log, "energy sentinel: largest balance / tolerance {:.4g} (step {}), external work {:.6g} J\n",
               summary.largest_energy_ratio, summary.largest_energy_ratio_step, sentinel->work());
  }
  fmt::print(log,
             "done: {} steps to t = {:.6g} s in {:.3f} s wall, {:.4g} particle-updates/s, {} particles ({} B state "
             "each), relative energy change {:+.3e}; output in {}\n",
             summary.steps, sim->time(), summary.wall_seconds, summary.particle_updates_per_second, summary.particles,
             summary.bytes_per_particle, summary.relative_energy_change, writer.directory().string());
  if (options.profile) {
    summary.profile = sim->profile();
    fmt::print(log,
               "profile (wall time per phase; G2P and the stress update run fused and are split by their CPU "
               "time):\n{}\n",
               format_profile(summary.profile));
    if (comm && comm->size() > 1) {  // where the ranks differ: the waiting of one is the other's extra work
      const StepProfile& p = summary.profile;
      // Every phase, then the compute (the four phases of the particles and the grid: equal particle counts and
      // unequal compute mean unequal cores), the stepping total and the particles on the rank.
      constexpr int n = step_phase_count + 3;
      std::array<double, n> most{};
      for (int k = 0; k < step_phase_count; ++k) most[k] = p[static_cast<StepPhase>(k)];
      most[step_phase_count] =
          p[StepPhase::p2g] + p[StepPhase::grid_update] + p[StepPhase::g2p] + p[StepPhase::stress_update];
      most[step_phase_count + 1] = p.stepping_seconds();
      most[n - 1] = static_cast<double>(sim->particle_count());
      std::array<double, n> least = most;
      comm->max(most);
      comm->min(least);
      for (int k = 0; k < n - 1; ++k) {
        const std::string_view name = k < step_phase_count    ? step_phase_names[k]
                                      : k == step_phase_count ? std::string_view("compute")
                                                              : std::string_view("stepping");
        fmt::print(log, "ranks' {}: min {:.4f} s, max {:.4f} s\n", name, least[k], most[k]);
      }
      fmt::print(log, "ranks' particles at the end: min {:.0f}, max {:.0f}\n", least[n - 1], most[n - 1]);
    }
  }
  return summary;
}

}  // namespace

void check_scene(const SceneDescription& scene, std::ostream& out, int ranks) {
  switch (scene.dimension) {
    case 1:
      return check<1>(scene, out, ranks);
    case 2:
      return check<2>(scene, out, ranks);
    default:
      return check<3>(scene, out, ranks);
  }
}

RunSummary run_scene(const SceneDescription& scene, const RunOptions& options, std::ostream& log) {
  switch (scene.dimension) {
    case 1:
      return run<1>(scene, options, log);
    case 2:
      return run<2>(scene, options, log);
    default:
      return run<3>(scene, options, log);
  }
}

}  // namespace mpm::app
