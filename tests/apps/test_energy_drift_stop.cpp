// The energy sentinel's actions through the `mpm` program (the run object, libmpm/include/mpm/run/run.hpp), on
// examples/02_two_disks with an energy tolerance of 0.1% of the largest energy: pure FLIP with hat functions gains
// about 0.3% of energy after the disks collide (the example's README), so the balance exceeds the tolerance on a
// check of the sentinel (every 50 steps). `warn` logs one warning and runs to the end; `stop` ends the run with exit
// status 3 at that step, its state the last frame, and no failure/ (the flight recorder follows a failing particle,
// and there is none). The Python package does the same: python/tests/test_run_policy.py.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "run_mpm.hpp"

namespace {

namespace fs = std::filesystem;

/// examples/02_two_disks with energy_tolerance 0.001 and on_energy_drift `action`, written to `dir`/scene.yaml.
std::string drifting_disks(const fs::path& dir, const std::string& action) {
  std::string yaml = cli::slurp(fs::path(MPM_SOURCE_DIR) / "examples" / "02_two_disks" / "scene.yaml");
  const std::string end = "  end_time: 3.5";
  yaml.replace(yaml.find(end), end.size(), end + "\n  energy_tolerance: 0.001\n  on_energy_drift: " + action);
  std::ofstream(dir / "scene.yaml") << yaml;
  return (dir / "scene.yaml").string();
}

/// The step of the sentinel's message ("energy sentinel: at step N"), or -1.
long long drift_step(const std::string& log) {
  std::smatch m;
  return std::regex_search(log, m, std::regex(R"(energy sentinel: at step (\d+))")) ? std::stoll(m[1].str()) : -1;
}

TEST(EnergyDrift, WarnLogsOneWarningAndRunsToTheEnd) {
  const fs::path dir = cli::scratch("drift_warn");
  const cli::Result r = cli::mpm("run " + drifting_disks(dir, "warn") + " -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto at = r.err.find("warning: energy sentinel: at step ");
  ASSERT_NE(at, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("warning: ", at + 1), std::string::npos) << "warned twice:\n" << r.err;
  EXPECT_EQ(drift_step(r.err) % 50, 0) << r.err;  // found on a check of the sentinel
  EXPECT_NE(r.err.find("done: 3500 steps"), std::string::npos) << r.err;
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(EnergyDrift, StopEndsTheRunWithStatusThreeAtTheStepOfTheDrift) {
  const fs::path dir = cli::scratch("drift_stop");
  const cli::Result r = cli::mpm("run " + drifting_disks(dir, "stop") + " -o " + (dir / "out").string(), dir);
  EXPECT_EQ(r.status, 3) << r.err;
  const long long step = drift_step(r.err);
  ASSERT_GT(step, 0) << r.err;
  for (const std::string part : {"error: energy sentinel: at step " + std::to_string(step),
                                 "(solver.on_energy_drift: stop)\nThe last good state was written to the output."})
    EXPECT_NE(r.err.find(part), std::string::npos) << "missing '" << part << "' in:\n" << r.err;
  EXPECT_EQ(r.err.find("warning: "), std::string::npos) << r.err;  // the stop, not a warning
  // the last frame is the state of that step (dt = 0.001 s)
  const std::string pvd = cli::slurp(dir / "out" / "particles.pvd");
  std::smatch last;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), std::regex(R"(timestep="([^"]+)\")"));
       it != std::sregex_iterator(); ++it)
    last = *it;
  EXPECT_NEAR(std::stod(last[1].str()), 0.001 * static_cast<double>(step), 1e-9) << pvd;
  EXPECT_FALSE(fs::exists(dir / "out" / "failure"));
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
