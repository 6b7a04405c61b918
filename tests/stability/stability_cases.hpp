#pragma once
/// \file stability_cases.hpp
/// Stiff and extreme cases: what a run does when the material is very stiff or nearly
/// incompressible, at hypervelocity, under extreme compression, with a body thinner than a cell, with a
/// fixed dt near the CFL bound, and over 1e5 steps. Each case runs through the same path as `mpm run`
/// (app::run_scene, or the MMS runner with an OutputWriter) into a directory, then reads back every file it
/// wrote. Scene-file cases leave their scene there too (DIR/scene.yaml), so that `mpm run` can repeat them. The tests
/// in this folder assert the outcomes; bench/verification_report prints them in docs/VERIFICATION.md.

#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "output_scan.hpp"

namespace mpm::verification {

struct StabilityOutcome {
  enum class Status { completed, stopped_by_guard, refused_by_loader };
  Status status = Status::completed;
  std::string message;  ///< the stability guard's or the scene loader's message (empty when completed)
  long long steps = 0;  ///< steps completed (the last good step when stopped)
  double time = 0;      ///< s, simulated time reached
  double wall_seconds = 0;
  /// The case's own measure (see its description), NaN when it has none: an error against the reference
  /// or the quantity the case is about (rebound velocity, |J - 1|, energy drift).
  double measured = std::numeric_limits<double>::quiet_NaN();
  std::string summary;  ///< one sentence with the numbers, for the report
  OutputScan output;    ///< what the run wrote (empty when refused)
  /// What the user was told besides `message`: the run's log (the warnings, among them the energy sentinel's
  /// "warning: energy sentinel: ..." with its hint, and its closing "largest balance / tolerance" line), and that
  /// largest ratio (> 1: it warned; 0 when the run did not complete).
  std::string log;
  double largest_energy_ratio = 0;
  /// Further named numbers of a case, for its test (e.g. "checkerboard" of the locking cases).
  std::map<std::string, double> measures;
  bool stopped() const { return status == Status::stopped_by_guard; }
  bool completed() const { return status == Status::completed; }
};

struct StabilityCase {
  std::string name;
  std::string description;  ///< the setup and what `measured` is
  std::function<StabilityOutcome(const std::filesystem::path& output_directory)> run;
};

/// Every case, the first set, then the extended ones (extended_stability_cases.hpp).
std::vector<StabilityCase> stability_cases();
/// The case called `name` (throws std::invalid_argument).
StabilityOutcome run_stability_case(const std::string& name, const std::filesystem::path& output_directory);

/// Runs the scene text `yaml` as `mpm run` does (app::run_scene) into `dir`, which is emptied first and keeps the
/// scene as DIR/scene.yaml, then reads back what the run wrote. `steps`: stop after that many (`mpm run --steps`).
StabilityOutcome run_scene_text(const std::string& yaml, const std::string& name,
                                const std::filesystem::path& output_directory,
                                std::optional<long long> steps = std::nullopt);

/// The bar of review §6.1.1 (mode 1, L = 25 m, E = 100 Pa unless given, rho = 1, fixed at x = 0, MUSL,
/// linear, FLIP) with `cells` cells and a fixed dt: max over the output frames of |v_cm - exact| / amplitude.
struct BarRun {
  StabilityOutcome outcome;
  double stable_dt = 0;  ///< the CFL bound h / (c + max|v|) of the initial state, s
};
BarRun run_bar(const std::filesystem::path& output_directory, double youngs_modulus, int cells, double dt_over_bound,
               double periods, int frames_per_period, const std::string& scheme = "musl");

}  // namespace mpm::verification
