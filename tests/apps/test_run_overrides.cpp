// `mpm run --steps N` and `--end-time T`: the run stops where asked, the output it writes is read back and
// found finite (tests/stability/output_scan.hpp); bad values exit with 2, name the option and the value,
// and write nothing. Every example scene runs for a few steps this way (CI runs each one, not only builds it).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "output_scan.hpp"
#include "run_mpm.hpp"

namespace fs = std::filesystem;

namespace {

using cli::scratch;

const fs::path good_scene = fs::path(MPM_SOURCE_DIR) / "tests" / "data" / "good_scene_2d.yaml";

/// The summary line (on stdout) says "done: N steps to t = T s".
std::string done_line(const std::string& out) {
  const auto at = out.find("done: ");
  return at == std::string::npos ? "" : out.substr(at, out.find('\n', at) - at);
}

TEST(RunOverrides, StepsStopsTheRunAfterNSteps) {
  const auto dir = scratch("steps");
  const auto r = cli::mpm("run " + good_scene.string() + " --steps 3 -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(done_line(r.out).rfind("done: 3 steps to t = ", 0), 0u) << r.out << r.err;
  const auto scan = mpm::verification::scan_output(dir / "out");
  EXPECT_TRUE(scan.all_finite());
  EXPECT_GE(scan.vtu_files, 2);       // the first frame and the last one
  EXPECT_EQ(scan.energy.size(), 2u);  // the same two rows in energy.csv
  EXPECT_EQ(scan.energy.back().at("step"), 3);
  fs::remove_all(dir);
}

TEST(RunOverrides, EndTimeReplacesTheScenesEndTime) {
  const auto dir = scratch("end_time");
  const auto r = cli::mpm("run " + good_scene.string() + " --end-time 0.001 -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(done_line(r.out).find(" to t = 0.001 s "), std::string::npos) << r.out << r.err;
  const auto scan = mpm::verification::scan_output(dir / "out");
  EXPECT_TRUE(scan.all_finite());
  ASSERT_FALSE(scan.energy.empty());
  EXPECT_NEAR(scan.energy.back().at("time"), 0.001, 1e-12);
  // Both: whichever comes first; one step of this scene is far shorter than 1 s.
  const auto both =
      cli::mpm("run " + good_scene.string() + " --end-time 1 --steps 2 -o " + (dir / "out2").string(), dir);
  ASSERT_EQ(both.status, 0) << both.err;
  EXPECT_EQ(done_line(both.out).rfind("done: 2 steps to t = ", 0), 0u) << both.out << both.err;
  fs::remove_all(dir);
}

TEST(RunOverrides, BadValuesExitWithTwoAndWriteNothing) {
  const auto dir = scratch("bad_overrides");
  const struct {
    const char* args;
    const char* message;
  } cases[] = {
      {"--steps 0", "--steps: expected a whole number of steps >= 1, got '0'"},
      {"--steps -3", "--steps: expected a whole number of steps >= 1, got '-3'"},
      {"--steps ten", "--steps: expected a whole number of steps >= 1, got 'ten'"},
      {"--steps 2.5", "--steps: expected a whole number of steps >= 1, got '2.5'"},
      {"--end-time 0", "--end-time: expected a positive end time in seconds, got '0'"},
      {"--end-time -1", "--end-time: expected a positive end time in seconds, got '-1'"},
      {"--end-time soon", "--end-time: expected a positive end time in seconds, got 'soon'"},
      {"--end-time inf", "--end-time: expected a positive end time in seconds, got 'inf'"},
      {"--end-time nan", "--end-time: expected a positive end time in seconds, got 'nan'"},
  };
  for (const auto& c : cases) {
    const fs::path out = dir / "out";
    const auto r = cli::mpm("run " + good_scene.string() + " " + c.args + " -o " + out.string(), dir);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << "output written for " << c.args;
  }
  fs::remove_all(dir);
}

TEST(RunOverrides, HelpDocumentsThem) {
  const auto dir = scratch("run_help");
  const auto r = cli::mpm("run --help", dir);
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--steps"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--end-time"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

#if defined(MPM_WITH_PLASTICITY) && defined(MPM_WITH_FLUIDS) && defined(MPM_WITH_THERMAL) && defined(MPM_WITH_CONTACT)
// Every scene shipped in examples/ runs: three steps each into a scratch directory, a clean exit, and every
// .vtu and .csv it wrote read back and finite.
TEST(RunOverrides, EveryExampleRunsThreeSteps) {
  int ran = 0;
  const auto dir = scratch("examples_run");
  for (const auto& folder : fs::directory_iterator(fs::path(MPM_SOURCE_DIR) / "examples")) {
    if (!folder.is_directory()) continue;
    for (const auto& entry : fs::directory_iterator(folder.path())) {
      if (entry.path().extension() != ".yaml") continue;
      // a user material needs the library its README builds: tests/user_material runs it with the test-built ones
      if (cli::slurp(entry.path()).find("model: user") != std::string::npos) continue;
      const fs::path out = dir / (folder.path().filename().string() + "_" + entry.path().stem().string());
      const auto r = cli::mpm("run " + entry.path().string() + " --steps 3 --threads 2 -o " + out.string(), dir);
      EXPECT_EQ(r.status, 0) << entry.path() << "\n" << r.err;
      EXPECT_EQ(done_line(r.out).rfind("done: 3 steps", 0), 0u) << entry.path() << "\n" << r.out << r.err;
      const auto scan = mpm::verification::scan_output(out);
      EXPECT_TRUE(scan.all_finite()) << entry.path() << ": " << (scan.bad.empty() ? "" : scan.bad.front());
      EXPECT_GE(scan.vtu_files, 2) << entry.path();
      EXPECT_GE(scan.energy.size(), 2u) << entry.path();
      fs::remove_all(out);
      ++ran;
    }
  }
  fs::remove_all(dir);
  EXPECT_GE(ran, 21);
}
#endif

}  // namespace
