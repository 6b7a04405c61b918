// The energy sentinel's actions through the `mpm` program (the run object, libmpm/include/mpm/run/run.hpp), on
// examples/02_two_disks at 40 x 40 cells (1,624 particles) with dt = 0.002 s and an energy tolerance of 0.2% of the
// largest energy: pure FLIP with hat functions gains strain energy after the disks collide, and the balance exceeds
// the tolerance on the sentinel's check at step 1300 (t = 2.6 s; measured: +0.0121 J against 0.0051 J). `warn` logs
// one warning and runs to the end; `stop` ends the run with exit status 3 at that step, its state the last frame,
// and no failure/ (the flight recorder follows a failing particle, and there is none). The Python package does the
// same: python/tests/test_run_policy.py.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <string>

#include "run_mpm.hpp"

namespace {

namespace fs = std::filesystem;

/// examples/02_two_disks at 40 x 40 cells, dt = 0.002 s, a frame every 0.25 s, energy_tolerance 0.002 and
/// on_energy_drift `action`, written to `dir`/scene.yaml.
std::string drifting_disks(const fs::path& dir, const std::string& action) {
  std::string yaml = cli::slurp(fs::path(MPM_SOURCE_DIR) / "examples" / "02_two_disks" / "scene.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = yaml.find(from);
    if (at == std::string::npos) throw std::runtime_error("'" + from + "' not in the two-disk scene");
    yaml.replace(at, from.size(), to);
  };
  replace("cell_size: 0.05", "cell_size: 0.025");
  replace("dt: 0.001", "dt: 0.002");
  replace("interval: 0.05", "interval: 0.25");
  replace("  end_time: 3.5", "  end_time: 3.5\n  energy_tolerance: 0.002\n  on_energy_drift: " + action);
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
  EXPECT_EQ(drift_step(r.err), 1300) << r.err;  // found on a check of the sentinel (every 50 steps)
  EXPECT_NE(r.out.find("done: 1750 steps"), std::string::npos) << r.out;  // the summary, on stdout
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(EnergyDrift, StopEndsTheRunWithStatusThreeAtTheStepOfTheDrift) {
  const fs::path dir = cli::scratch("drift_stop");
  const cli::Result r = cli::mpm("run " + drifting_disks(dir, "stop") + " -o " + (dir / "out").string(), dir);
  EXPECT_EQ(r.status, 3) << r.err;
  const long long step = drift_step(r.err);
  ASSERT_EQ(step, 1300) << r.err;
  for (const std::string& part : {"error: energy sentinel: at step " + std::to_string(step),
                                  std::string("(solver.on_energy_drift: stop)\nThe last good state was written to "
                                              "the output.")})
    EXPECT_NE(r.err.find(part), std::string::npos) << "missing '" << part << "' in:\n" << r.err;
  EXPECT_EQ(r.err.find("warning: "), std::string::npos) << r.err;  // the stop, not a warning
  // the last frame is the state of that step (dt = 0.002 s), after the frames every 0.25 s before it
  const std::string pvd = cli::slurp(dir / "out" / "particles.pvd");
  const std::regex timestep(R"(timestep="([^"]+)\")");
  std::smatch last;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), timestep); it != std::sregex_iterator(); ++it) last = *it;
  EXPECT_NEAR(std::stod(last[1].str()), 0.002 * static_cast<double>(step), 1e-9) << pvd;
  EXPECT_TRUE(fs::exists(dir / "out" / "particles_000011.vtu"));  // t = 0, 0.25, ..., 2.5 s, then 2.6 s
  EXPECT_FALSE(fs::exists(dir / "out" / "particles_000012.vtu"));
  EXPECT_FALSE(fs::exists(dir / "out" / "failure"));
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
