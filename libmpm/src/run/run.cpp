#include "mpm/run/run.hpp"

#include <fmt/format.h>

#include <chrono>

#include "mpm/diagnostics/energy_sentinel.hpp"
#include "mpm/history/history_kind.hpp"
#include "mpm/simulation/step_profile.hpp"

namespace mpm {
namespace {

using Clock = std::chrono::steady_clock;

/// Simulation::step_flags of the run: what every rank of a distributed run must agree on after a step.
constexpr unsigned checkpoint_due = 1, interrupt = 2;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// gravity_stage.csv: `step, dt, unbalanced_force_ratio, kinetic_energy`, one row per step of the stage.
void write_gravity_stage(const std::filesystem::path& directory, const GravityStageReport& report) {
  io::CsvLog table(directory / "gravity_stage.csv", {"step", "dt", "unbalanced_force_ratio", "kinetic_energy"});
  for (const auto& r : report.rows) table.append({static_cast<double>(r.step), r.dt, r.ratio, r.kinetic_energy});
}

}  // namespace

template <int Dim>
Run<Dim>::Run(const SceneDescription& scene, std::unique_ptr<Simulation<Dim>> sim, RunLog& log,
              std::vector<std::string> warnings, std::optional<GravityStageReport> gravity_stage)
    : scene_(scene),
      sim_(std::move(sim)),
      log_(log),
      scene_warnings_(std::move(warnings)),
      gravity_stage_(std::move(gravity_stage)) {
  // The histories' checks at t = 0 see every particle (before a distributed run shares them out).
  built_histories_ = build_histories<Dim>(scene_, *sim_, scene_warnings_);
}

template <int Dim>
Run<Dim>::~Run() = default;

template <int Dim>
void Run<Dim>::log_warnings() {
  for (const auto& w : scene_warnings_) log_.line("warning: " + w);
}

template <int Dim>
void Run<Dim>::start(RunOutput output) {
  output_ = std::move(output);
  const bool rank_zero = !output_.comm || output_.comm->rank() == 0;
  if (!output_.directory.empty()) {
    const auto& o = scene_.output;
    writer_ = std::make_unique<OutputWriter<Dim>>(output_.directory, o.prefix, o.fields, o.grid, o.interval,
                                                  output_.restart, output_.comm);
    writer_->set_field_data(output_.field_data);
    // every rank samples the histories (their sums are collective); rank 0 writes them
    histories_ = std::make_unique<HistoryWriter<Dim>>(writer_->directory(), std::move(built_histories_),
                                                      output_.restart, rank_zero);
    // The scheme's own per-step table (the implicit scheme's solver.csv), one row per step; a restart starts it anew.
    if (const std::string_view file = sim_->scheme().step_log_file(); !file.empty())
      step_log_ =
          std::make_unique<io::CsvLog>(writer_->directory() / std::string(file), sim_->scheme().step_log_columns());
    if (rank_zero) io::write_view_script(writer_->directory() / "view.py", output_.view_script);
    if (rank_zero && gravity_stage_ && !output_.restart) write_gravity_stage(writer_->directory(), *gravity_stage_);
  } else {
    output_.checkpoints = nullptr;                               // a checkpoint holds the output's state
    if (output_.keep_history_rows && !built_histories_.empty())  // sampled for the rows only, no file
      histories_ =
          std::make_unique<HistoryWriter<Dim>>(std::filesystem::path(), std::move(built_histories_), nullptr, false);
  }
  if (histories_) histories_->keep_rows(output_.keep_history_rows);
  built_histories_.clear();
  if (gravity_stage_ && !output_.restart && rank_zero) log_.line(gravity_stage_->summary());
  record_.warned.assign(sim_->bodies().size(), false);
  record_.initial_energy = sim_->energy().total();
  if (output_.restart) {
    record_.restore(*output_.restart);
    last_checkpoint_step_ = sim_->step();  // the checkpoint continued is this step's
  }
  if (output_.profile) sim_->enable_profiling();
}

template <int Dim>
std::filesystem::path Run<Dim>::output_directory() const {
  return writer_ ? writer_->directory() : std::filesystem::path();
}

template <int Dim>
std::vector<std::string> Run<Dim>::warnings() const {
  std::vector<std::string> all = scene_warnings_;
  all.insert(all.end(), record_.warnings.begin(), record_.warnings.end());
  return all;
}

template <int Dim>
void Run<Dim>::apply_particle_changes() {
  if (!changed_) return;
  sim_->particles_changed();
  changed_ = false;
}

template <int Dim>
void Run<Dim>::warn(std::string message) {
  record_.warnings.push_back(std::move(message));
  log_.line("warning: " + record_.warnings.back());
}

template <int Dim>
void Run<Dim>::write(bool always) {
  const auto t0 = output_.profile ? Clock::now() : Clock::time_point{};  // output is timed only when profiling
  if (writer_) always ? writer_->write(*sim_) : static_cast<void>(writer_->write_if_due(*sim_));
  if (histories_) always ? histories_->write(*sim_) : histories_->write_if_due(*sim_);
  if (output_.profile) sim_->add_to_profile(StepPhase::output, StepProfile::since(t0));
}

template <int Dim>
void Run<Dim>::check_state() {
  for (std::size_t b = 0; b < sim_->bodies().size(); ++b) {
    if (record_.warned[b]) continue;
    const auto& body = sim_->bodies()[b];
    const std::string message = body.material->state_warning(body.particles);
    if (message.empty()) continue;
    record_.warned[b] = true;
    warn(fmt::format("body {} at t = {:.6g} s: {}", body.name, sim_->time(), message));
  }
}

template <int Dim>
void Run<Dim>::check_energy() {
  const EnergySentinel<Dim>* sentinel = sim_->energy_sentinel();
  if (!sentinel || !sentinel->drift() || sentinel->drift()->step != sim_->step()) return;
  const std::string message = sentinel->drift()->message();
  if (sentinel->action() == EnergyDriftAction::stop) {
    StabilityReport report;
    report.step = sim_->step();
    report.time = sim_->time();
    report.field = "energy_balance";
    report.detail = message + " (solver.on_energy_drift: stop)";
    throw StabilityError(report);
  }
  warn(message);
}

template <int Dim>
void Run<Dim>::check_outflow() {
  // The first departure of each body through each outflow face, in the step it happened (the books: energy.csv).
  for (const auto& notice : sim_->boundary().outflow_notices())
    if (notice.step == sim_->step()) warn(notice.message());
}

template <int Dim>
void Run<Dim>::write_checkpoint() {
  if (!output_.checkpoints || sim_->step() == last_checkpoint_step_) return;  // at most one per step
  const auto t0 = Clock::now();
  StateArchive archive;
  sim_->save_state(archive);
  writer_->save_state(archive);
  histories_->save_state(archive);
  record_.save(archive);
  last_checkpoint_ = output_.checkpoints->write(archive, sim_->step(), sim_->time());
  last_checkpoint_step_ = sim_->step();
  if (last_checkpoint_->empty()) return;  // a distributed run's other ranks (rank 0 writes it)
  log_.line(fmt::format("checkpoint: {} (step {}, t = {:.9g} s; {:.3g} MB in {:.3g} s)", last_checkpoint_->string(),
                        sim_->step(), sim_->time(),
                        1e-6 * static_cast<double>(std::filesystem::file_size(*last_checkpoint_)), seconds_since(t0)));
}

template <int Dim>
typename Run<Dim>::Next Run<Dim>::after_step(RunObserver<Dim>* observer) {
  if (step_log_) step_log_->append(sim_->scheme().step_log_row());
  write(false);
  check_energy();
  check_outflow();
  if (sim_->step() % state_check_interval == 0) check_state();
  // A wall-clock checkpoint interval expires, and a stop is requested, at different steps on the ranks: all write
  // when any is due and all stop after the step where any one asked. Both flags were asked at the end of the step
  // and merged over the ranks in the step's own reduction (Simulation::set_step_flags).
  if (sim_->step_flags() & checkpoint_due) write_checkpoint();
  if (sim_->step_flags() & interrupt) return Next::interrupt;
  const bool stop = observer && observer->after_step(*sim_);
  apply_particle_changes();  // made by the observer through views, before the next step
  return stop ? Next::stop : Next::go_on;
}

template <int Dim>
template <class Steps>
void Run<Dim>::stepping(RunObserver<Dim>* observer, Steps&& steps) {
  apply_particle_changes();
  if (!started_) {
    started_ = true;
    if (!output_.restart) write(false);  // the first frame (a restart's frames up to its checkpoint are there)
  }
  try {
    sim_->set_step_flags([this, observer](Index step, Real time) {
      return (output_.checkpoints && output_.checkpoints->due(time) ? checkpoint_due : 0u) |
             (observer && observer->interrupt_requested(step) ? interrupt : 0u);
    });
    struct Unset {  // the flight recorder's replays and the last frame's writes ask no flags
      Simulation<Dim>& sim;
      ~Unset() { sim.set_step_flags({}); }
    } unset{*sim_};
    steps();
  } catch (const StabilityError& e) {
    write(true);  // the last good state: the guard rolled the simulation back, the sentinel stops after its step
    if (observer) observer->on_stability_error(*sim_, e.report());
    throw;
  }
}

template <int Dim>
RunEnd Run<Dim>::conclude(Next next, bool was_finished, bool always) {
  if (next == Next::interrupt) {
    // The checkpoint first, then the last frame: a restart replaces that frame (it is after the checkpoint).
    write_checkpoint();
    write(true);
    return RunEnd::interrupted;
  }
  if (always || (!was_finished && sim_->finished())) {
    check_state();
    if (output_.checkpoints && output_.checkpoints->at_end() && sim_->finished())
      write_checkpoint();  // a fork may continue past the end
    write(true);
  }
  if (sim_->finished()) return RunEnd::end_time;
  return next == Next::stop ? RunEnd::stopped : RunEnd::step_limit;
}

template <int Dim>
RunEnd Run<Dim>::run(std::optional<Index> last_step, RunObserver<Dim>* observer) {
  const bool was_finished = sim_->finished();
  Next next = Next::go_on;
  stepping(observer, [&] {
    struct Halt {
      Next next;
    };
    const auto start = Clock::now();
    try {
      sim_->run(
          [&](const Simulation<Dim>&) {
            if (const Next n = after_step(observer); n != Next::go_on) throw Halt{n};
          },
          last_step);
    } catch (const Halt& halt) {
      next = halt.next;
    }
    stepping_seconds_ = seconds_since(start);
  });
  return conclude(next, was_finished, true);
}

template <int Dim>
RunEnd Run<Dim>::step(RunObserver<Dim>* observer) {
  const bool was_finished = sim_->finished();
  Next next = Next::go_on;
  stepping(observer, [&] {
    sim_->advance(was_finished ? sim_->next_time_step() : sim_->time_step_toward(sim_->settings().end_time));
    next = after_step(observer);
  });
  return conclude(next, was_finished, false);
}

template <int Dim>
RunEnd Run<Dim>::advance_to(Real t, RunObserver<Dim>* observer) {
  const bool was_finished = sim_->finished();
  Next next = Next::go_on;
  stepping(observer, [&] {
    while (next == Next::go_on && !sim_->reached(t)) {
      sim_->advance(sim_->time_step_toward(t));
      next = after_step(observer);
    }
  });
  return conclude(next, was_finished, false);
}

template <int Dim>
std::unique_ptr<OutputWriter<Dim>> Run<Dim>::make_writer(const std::filesystem::path& directory) const {
  const auto& o = scene_.output;
  auto writer = std::make_unique<OutputWriter<Dim>>(directory, o.prefix, o.fields, o.grid, o.interval);
  writer->set_field_data(output_.field_data);
  io::write_view_script(writer->directory() / "view.py", output_.view_script);
  return writer;
}

template <int Dim>
void Run<Dim>::write_frame(const std::filesystem::path& directory) {
  apply_particle_changes();
  const std::string key = std::filesystem::weakly_canonical(directory).string();
  if (writer_ && key == std::filesystem::weakly_canonical(writer_->directory()).string()) {
    writer_->write(*sim_);
    return;
  }
  auto& writer = frames_[key];
  if (!writer) writer = make_writer(directory);
  writer->write(*sim_);
}

template class Run<1>;
template class Run<2>;
template class Run<3>;

}  // namespace mpm
