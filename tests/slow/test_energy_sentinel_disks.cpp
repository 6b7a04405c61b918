// The energy sentinel on its reference case: the two disks of examples/02_two_disks at 200 cells per side with
// dt = 0.002 s (40,216 particles, MUSL, 1,750 steps to 3.5 s). With FLIP and linear hats the total energy grows
// by 37% and the sentinel warns, quoting the hint table's FLIP row; with each remedy that row names (a PIC
// fraction, quadratic B-splines, cpGIMP) the balance stays below the tolerance (0.05 of the largest energy).
// Measured numbers: docs/VERIFICATION.md, "Energy sentinel". Label slow: 15-60 s of CPU per run.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "mpm/app/run_scene.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm {
namespace {

namespace fs = std::filesystem;

/// examples/02_two_disks/scene.yaml at 200 cells per side, dt = 0.002 s, with `from` replaced by `to`.
std::string fine_disks(const std::string& from = "", const std::string& to = "") {
  std::ifstream in(fs::path(MPM_SOURCE_DIR) / "examples" / "02_two_disks" / "scene.yaml");
  std::stringstream s;
  s << in.rdbuf();
  std::string yaml = s.str();
  auto replace = [&](const std::string& a, const std::string& b) {
    const auto at = yaml.find(a);
    if (at == std::string::npos) throw std::runtime_error("'" + a + "' not in the two-disk scene");
    yaml.replace(at, a.size(), b);
  };
  replace("cell_size: 0.05", "cell_size: 0.005");
  replace("dt: 0.001", "dt: 0.002");
  replace("interval: 0.05", "interval: 0");
  if (!from.empty()) replace(from, to);
  return yaml;
}

struct SentinelRun {
  app::RunSummary summary;
  std::string log;
};

SentinelRun run(const std::string& yaml, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("mpm_sentinel_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  app::RunOptions options;
  options.output_directory = dir;
  std::ostringstream log;
  SentinelRun r;
  r.summary = app::run_scene(parse_scene(yaml, name + ".yaml"), options, log, log);
  r.log = log.str();
  fs::remove_all(dir);
  return r;
}

TEST(EnergySentinelDisks, FlipWithHatsWarnsWithTheFlipHint) {
  const SentinelRun r = run(fine_disks(), "flip");
  std::printf("[ measured ] FLIP, hats: largest balance / tolerance %.4g at step %lld; relative energy change %+.4e\n",
              r.summary.largest_energy_ratio, r.summary.largest_energy_ratio_step, r.summary.relative_energy_change);
  EXPECT_EQ(r.summary.particles, 40216u);
  EXPECT_EQ(r.summary.steps, 1750);
  EXPECT_GT(r.summary.relative_energy_change, 0.30);  // +37.3% measured
  EXPECT_GT(r.summary.largest_energy_ratio, 1);
  const auto at = r.log.find("warning: energy sentinel: at step ");
  ASSERT_NE(at, std::string::npos) << r.log;
  EXPECT_EQ(r.log.find("warning: energy sentinel", at + 1), std::string::npos) << "warned twice:\n" << r.log;
  for (const char* part : {"flip_fraction: 0.99", "quadratic_bspline", "cpgimp", "grew most", "+37.3%"})
    EXPECT_NE(r.log.find(part, at), std::string::npos) << "missing '" << part << "' in:\n" << r.log;
}

// `on_energy_drift: stop` through the program: status 3 at the step of the warning, the message names the key,
// the state of that step is the last frame, and there is no failure/ (the guard's, for a failing particle).
TEST(EnergySentinelDisks, StopEndsTheProgramWithStatusThree) {
  const fs::path dir = fs::temp_directory_path() / ("mpm_sentinel_stop_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.yaml") << fine_disks("  end_time: 3.5", "  end_time: 3.5\n  on_energy_drift: stop");
  const std::string command = std::string(MPM_EXECUTABLE) + " run " + (dir / "scene.yaml").string() + " -o " +
                              (dir / "out").string() + " > " + (dir / "log").string() + " 2>&1";
  const int raw = std::system(command.c_str());
  std::ifstream in(dir / "log");
  std::stringstream log;
  log << in.rdbuf();
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 3) << log.str();
  for (const char* part :
       {"energy sentinel: at step ", "(solver.on_energy_drift: stop)", "Hint: ", "The last good state was written"})
    EXPECT_NE(log.str().find(part), std::string::npos) << "missing '" << part << "' in:\n" << log.str();
  EXPECT_TRUE(fs::exists(dir / "out" / "particles_000001.vtu"));
  EXPECT_FALSE(fs::exists(dir / "out" / "failure"));
  fs::remove_all(dir);
}

void expect_no_warning(const std::string& from, const std::string& to, const std::string& name) {
  const SentinelRun r = run(fine_disks(from, to), name);
  std::printf("[ measured ] %s: largest balance / tolerance %.4g at step %lld; relative energy change %+.4e\n",
              name.c_str(), r.summary.largest_energy_ratio, r.summary.largest_energy_ratio_step,
              r.summary.relative_energy_change);
  EXPECT_EQ(r.summary.steps, 1750);
  EXPECT_LT(r.summary.largest_energy_ratio, 1);
  EXPECT_EQ(r.log.find("energy sentinel: at step"), std::string::npos) << r.log;
}

TEST(EnergySentinelDisks, PicFractionDoesNotWarn) {
  expect_no_warning("flip_fraction: 1.0", "flip_fraction: 0.99", "pic");
}
TEST(EnergySentinelDisks, QuadraticBsplinesDoNotWarn) {
  expect_no_warning("shape_function: linear", "shape_function: quadratic_bspline", "quadratic_bspline");
}
TEST(EnergySentinelDisks, CpGimpDoesNotWarn) {
  expect_no_warning("shape_function: linear", "shape_function: cpgimp", "cpgimp");
}

}  // namespace
}  // namespace mpm
