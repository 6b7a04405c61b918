#pragma once
/// \file run_console.hpp
/// What `mpm run` shows and decides while the run object steps (mpm/run/run.hpp): its log (the run's warnings and
/// notes, each on a line of its own after the progress line), the progress line on a terminal (step, simulated
/// time, particle-updates per second, time left), the stop signals (stop_signals.hpp) and the test seams of
/// RunOptions, and the flight recorder (flight_recorder.hpp) after the stability guard stopped the run.

#include <chrono>
#include <filesystem>
#include <iosfwd>
#include <string>

#include "mpm/app/run_scene.hpp"
#include "mpm/run/run_log.hpp"
#include "mpm/run/run_observer.hpp"

namespace mpm::app {

template <int Dim>
class RunConsole final : public RunLog, public RunObserver<Dim> {
 public:
  /// `scene` and `options` must outlive it.
  RunConsole(std::ostream& log, const SceneDescription& scene, const RunOptions& options);

  void line(const std::string& text) override;
  /// Ends the progress line, if one is shown, so that what follows starts a line.
  void end_progress_line();
  /// The steps start now from `sim`'s step (the progress line's rate and time left count from here); a failure/
  /// of the flight recorder goes into `output_directory`.
  void begin(const Simulation<Dim>& sim, std::filesystem::path output_directory);

  /// A stop signal arrived (or the test seam sends one during this step).
  bool interrupt_requested(Index step) override;
  /// The progress line, at most every half second (and the test seam's failure of a rank).
  bool after_step(const Simulation<Dim>& sim) override;
  /// The flight recorder's failure/ for a failing particle; a failure to write it is logged.
  void on_stability_error(Simulation<Dim>& sim, const StabilityReport& report) override;

 private:
  using Clock = std::chrono::steady_clock;
  std::ostream& log_;
  const SceneDescription& scene_;
  const RunOptions& options_;
  std::filesystem::path output_directory_;
  Clock::time_point start_, last_print_;
  Index first_step_ = 0;
  bool line_open_ = false;  ///< a progress line is shown and not ended
};

/// The command that runs `scene` as `options` did (for the flight recorder's diagnosis).
std::string run_command(const SceneDescription& scene, const RunOptions& options);

}  // namespace mpm::app
