#include "mpm/app/run_console.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <ostream>

#include "mpm/app/flight_recorder.hpp"
#include "mpm/diagnostics/energy_sentinel.hpp"

namespace mpm::app {

std::string run_command(const SceneDescription& scene, const RunOptions& options) {
  std::string command = "mpm run " + scene.file;
  if (options.output_directory) command += " -o " + options.output_directory->string();
  if (options.end_time) command += fmt::format(" --end-time {}", *options.end_time);
  if (options.steps) command += fmt::format(" --steps {}", *options.steps);
  if (options.restart) command += " --restart " + options.restart->string();
  for (const auto& line : options.overrides) command += "  # with " + line;
  return command;
}

template <int Dim>
RunConsole<Dim>::RunConsole(std::ostream& log, const SceneDescription& scene, const RunOptions& options)
    : log_(log), scene_(scene), options_(options) {}

template <int Dim>
void RunConsole<Dim>::line(const std::string& text) {
  end_progress_line();
  log_ << text << '\n';
}

template <int Dim>
void RunConsole<Dim>::end_progress_line() {
  if (!line_open_) return;
  log_ << '\n';
  line_open_ = false;
}

template <int Dim>
void RunConsole<Dim>::begin(const Simulation<Dim>& sim, std::filesystem::path output_directory) {
  output_directory_ = std::move(output_directory);
  first_step_ = sim.step();
  start_ = last_print_ = Clock::now();
}

template <int Dim>
bool RunConsole<Dim>::interrupt_requested(Index step) {
  if (options_.test.signal) raise_test_signal(*options_.test.signal, step);  // a signal "during" this step
  return StopSignals::requested() != 0;
}

template <int Dim>
bool RunConsole<Dim>::after_step(const Simulation<Dim>& s) {
  if (options_.test.failure)
    fail_for_test(*options_.test.failure, options_.communicator ? options_.communicator->rank() : 0, s.step());
  if (!options_.progress) return false;
  const auto now = Clock::now();
  if (now - last_print_ < std::chrono::milliseconds(500)) return false;
  last_print_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double rate = static_cast<double>(s.particle_count()) * static_cast<double>(s.step() - first_step_) / wall;
  double eta = wall * (s.settings().end_time - s.time()) / std::max(s.time(), 1e-300);
  if (options_.steps)
    eta = std::min(
        eta, wall * static_cast<double>(*options_.steps - s.step()) / static_cast<double>(s.step() - first_step_));
  fmt::print(log_, "\rstep {:>8}  t = {:<12.6g} s  {:9.3g} particle-updates/s  ETA {:7.1f} s ", s.step(), s.time(),
             rate, eta);
  log_.flush();
  line_open_ = true;
  return false;
}

template <int Dim>
void RunConsole<Dim>::on_stability_error(Simulation<Dim>& sim, const StabilityReport& report) {
  end_progress_line();
  if (report.particle < 0) return;  // the energy sentinel's stop: no particle to follow
  // A distributed run: every rank replays (collective steps), rank 0 writes.
  try {
    const EnergySentinel<Dim>* sentinel = sim.energy_sentinel();
    const FlightRecord r = record_failure(sim, report, sentinel ? sentinel->context() : HintContext{},
                                          output_directory_, scene_.output.fields, run_command(scene_, options_));
    fmt::print(log_, "flight recorder: {} (steps {} to {}, {} frames; diagnosis.txt)\n", r.directory.string(),
               r.first_step, report.step, r.frames);
  } catch (const std::exception& e) {
    fmt::print(log_, "flight recorder: failure/ not written: {}\n", e.what());
  }
}

template class RunConsole<1>;
template class RunConsole<2>;
template class RunConsole<3>;

}  // namespace mpm::app
