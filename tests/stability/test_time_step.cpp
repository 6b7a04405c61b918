// The time step at the CFL bound (eq. 2.73) and over a long run: a fixed dt of 0.9 times the bound runs and
// keeps the bar accurate; 1.1 times the bound is refused before anything is written, in the library and by
// the `mpm` program (exit status 2, the message naming file:line:column, solver.dt and the bound); 1e5
// steps keep the energy; a run stopped by the guard ends the program with status 3. Setups:
// stability_cases.cpp.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "stability_test_support.hpp"

namespace mpm::verification {
namespace {

namespace fs = std::filesystem;

struct ProgramRun {
  int status = -1;
  std::string err;
};

ProgramRun mpm_run(const fs::path& scene, const fs::path& out) {
  const fs::path err = out.parent_path() / (out.filename().string() + ".stderr");
  const std::string cmd = std::string(MPM_EXECUTABLE) + " run " + scene.string() + " -o " + out.string() +
                          " > /dev/null 2> " + err.string() + " < /dev/null";
  const int raw = std::system(cmd.c_str());
  ProgramRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(err);
  std::stringstream s;
  s << in.rdbuf();
  r.err = s.str();
  return r;
}

// Bar mode 1 (16 cells, MUSL, FLIP) with dt = 0.9 h / (c + max|v|) = 0.13923 s: stable; the centre-of-mass
// velocity is off by 4.66% of the amplitude at worst over one period (0.92% at 0.1 times the bound: the
// time-integration error of a step near the bound); the energy changes by -1.7e-3.
TEST(TimeStep, FixedStepAtNineTenthsOfTheBoundRuns) {
  const auto dir = scratch("dt09");
  const StabilityOutcome o = run_stability_case("fixed_dt_0.9", dir);
  std::printf("[ measured ] %s\n", o.summary.c_str());
  ASSERT_TRUE(o.completed()) << o.message;
  EXPECT_LT(o.measured, 0.06);
  EXPECT_LT(std::abs(o.output.energy_change()), 5e-3);
  expect_clean_output(o);
  fs::remove_all(dir);
}

// 1.1 times the bound is refused by the scene loader, with the bound in the message, and the program
// exits with status 2 and writes nothing.
TEST(TimeStep, FixedStepAboveTheBoundIsRefused) {
  const auto dir = scratch("dt11");
  const StabilityOutcome o = run_stability_case("fixed_dt_1.1", dir);
  ASSERT_EQ(o.status, StabilityOutcome::Status::refused_by_loader) << o.summary;
  EXPECT_NE(o.message.find("solver.dt: dt = 0.170174 s is larger than the stable time step 0.154703 s"),
            std::string::npos)
      << o.message;
  EXPECT_EQ(o.output.vtu_files, 0);

  const ProgramRun r = mpm_run(dir / "scene.yaml", dir / "out");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("scene.yaml:6:"), std::string::npos) << r.err;  // the line of `dt`
  EXPECT_NE(r.err.find("use dt <= 0.154703 or `cfl` instead"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

// 1e5 steps of the bar (16 cells, dt = 0.1 h/c, 156 periods of mode 1, MUSL, pure FLIP): the total energy
// ends +2.5e-3 from its initial value and never grows by more than 6.2e-3 over the 101 frames.
TEST(TimeStep, LongRunKeepsTheEnergy) {
  const auto dir = scratch("long");
  const StabilityOutcome o = run_stability_case("long_run", dir);
  std::printf("[ measured ] %s\n", o.summary.c_str());
  ASSERT_TRUE(o.completed()) << o.message;
  EXPECT_EQ(o.steps, 100000);
  EXPECT_LT(std::abs(o.measured), 5e-3);
  EXPECT_LT(o.output.max_energy_growth(), 1e-2);
  EXPECT_EQ(o.output.vtu_files, 101);
  expect_clean_output(o);
  fs::remove_all(dir);
}

// The guard through the program: the USL hypervelocity impact ends with status 3, the message on stderr
// and a last good frame with finite values only.
TEST(TimeStep, GuardStopThroughTheProgramExitsWithThree) {
  const auto dir = scratch("guard_cli");
  run_stability_case("hypervelocity_usl", dir / "case");
  const ProgramRun r = mpm_run(dir / "case" / "scene.yaml", dir / "out");
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("field 'deformation_gradient': det F = -"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("The last good state was written"), std::string::npos) << r.err;
  const OutputScan scan = scan_output(dir / "out");
  EXPECT_GE(scan.vtu_files, 2);
  EXPECT_TRUE(scan.all_finite());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mpm::verification
