// An open-topped tank through the `mpm` program (the run object, libmpm/include/mpm/run/run.hpp): the first
// particles of a body leaving through an outflow face are named once, as a warning, in the step they leave; the
// summary gives the face's books; and the summary's relative energy change counts the energy that left as booked,
// not lost. Scene: tests/distributed/scenes/outflow_splash.yaml (a water column thrown up at 6 m/s through y_max).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include "run_mpm.hpp"

namespace {

namespace fs = std::filesystem;

TEST(OutflowRun, TheFirstDepartureIsWarnedOnceAndTheSummaryBooksIt) {
  const fs::path dir = cli::scratch("outflow_run");
  const std::string scene =
      (fs::path(MPM_SOURCE_DIR) / "tests" / "distributed" / "scenes" / "outflow_splash.yaml").string();
  const cli::Result r = cli::mpm("run " + scene + " -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto first = r.err.find("warning: body water: ");
  ASSERT_NE(first, std::string::npos) << r.err;
  EXPECT_NE(r.err.find("through y_max", first), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("warning: body water: ", first + 1), std::string::npos) << "warned twice:\n" << r.err;
  // The warning on stderr, the summary (the outflow's books, the energy change) on stdout.
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("outflow y_max: "), std::string::npos) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(outflow y_max: (\d+) particles, mass ([0-9.e+-]+) kg)")))
      << r.out;
  EXPECT_GT(std::stoi(m[1].str()), 0);
  // The column is 0.8 x 0.8 m of water (640 kg per metre); what left is a part of it.
  EXPECT_GT(std::stod(m[2].str()), 0.0);
  EXPECT_LT(std::stod(m[2].str()), 640.0);
  // Without the outflow's energy the change would be the share that left (tens of percent); with it, the time
  // discretisation's loss only (the open-tank test of test_outflow.cpp: a few 1e-4).
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(relative energy change ([-+0-9.e]+))"))) << r.out;
  EXPECT_LT(std::abs(std::stod(m[1].str())), 0.02) << r.out;
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
