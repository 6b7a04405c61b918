// The gravity stage (`solver.gravity_stage`, docs/theory.md §20) through the `mpm` program: its line in the log,
// gravity_stage.csv, a stage that does not settle (stopped at its key with nothing written, or run on with a
// warning). Restart after the stage: tests/apps/test_restart.cpp (InterruptedRun.gravity_stage).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_mpm.hpp"

namespace fs = std::filesystem;

namespace {

using cli::mpm;
using cli::scratch;
using cli::slurp;

/// A laterally confined elastic column from zero stress, settled by the stage (its keys `stage`), then 0.02 s.
std::string column(const std::string& stage) {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [1, 2.5], cell_size: 0.1, boundary: {x_min: slip, x_max: slip, y_min: "
         "fixed}}\n"
         "materials: {soil: {model: linear_elastic, density: 2000, youngs_modulus: 1.0e7, poisson_ratio: 0.3}}\n"
         "bodies: [{name: column, material: soil, shape: {type: box, min: [0, 0], max: [1, 2]}}]\n"
         "solver:\n"
         "  cfl: 0.5\n"
         "  end_time: 0.02\n"
         "  gravity: [0, -10]\n"
         "  gravity_stage: " +
         stage + "  # the stage\n";
}

/// The rows of a CSV file with a header, as numbers.
std::vector<std::vector<double>> rows(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> out;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) row.push_back(std::stod(cell));
    out.push_back(row);
  }
  return out;
}

TEST(GravityStageRun, LogsItsEndAndWritesItsRatioPerStep) {
  const fs::path dir = scratch("gravity_stage_run");
  std::ofstream(dir / "column.yaml") << column("{tolerance: 1.0e-4}");
  const auto r = mpm("run " + (dir / "column.yaml").string() + " -o " + (dir / "out").string(), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("gravity stage: at rest after"), std::string::npos) << r.err;
  // the top row's settlement, 2.972 mm (the top surface's static rho g H^2 / (2 M) = 2.971 mm)
  EXPECT_NE(r.err.find("largest displacement 0.00297 m)"), std::string::npos) << r.err;
  const auto table = rows(dir / "out" / "gravity_stage.csv");
  ASSERT_GT(table.size(), 10u);
  std::printf("[ measured ] %zu steps; unbalanced force ratio %.3g at the first step, %.3g at the last\n", table.size(),
              table.front()[2], table.back()[2]);
  EXPECT_GT(table.front()[2], 0.5);  // nothing carries the weight yet
  for (std::size_t k = table.size() - 10; k < table.size(); ++k) EXPECT_LT(table[k][2], 1e-4);
  // the run starts at rest: the first frame's energy.csv row has no kinetic energy
  const auto energy = rows(dir / "out" / "energy.csv");
  ASSERT_FALSE(energy.empty());
  EXPECT_EQ(energy.front()[0], 0);  // time
  EXPECT_EQ(energy.front()[2], 0);  // kinetic_energy
  fs::remove_all(dir);
}

TEST(GravityStageRun, ThatDoesNotSettleStopsAtItsKeyOrWarns) {
  const fs::path dir = scratch("gravity_stage_unsettled");
  std::ofstream(dir / "stop.yaml") << column("{max_steps: 20}");
  const auto stop = mpm("run " + (dir / "stop.yaml").string() + " -o " + (dir / "stop").string(), dir);
  EXPECT_EQ(stop.status, 2) << stop.err;
  EXPECT_NE(stop.err.find((dir / "stop.yaml").string() + ":9:"), std::string::npos) << stop.err;
  EXPECT_NE(stop.err.find("solver.gravity_stage: the bodies did not come to rest under gravity"), std::string::npos)
      << stop.err;
  EXPECT_FALSE(fs::exists(dir / "stop"));
  std::ofstream(dir / "warn.yaml") << column("{max_steps: 20, on_no_equilibrium: warn}");
  const auto warn = mpm("run " + (dir / "warn.yaml").string() + " -o " + (dir / "warn").string(), dir);
  EXPECT_EQ(warn.status, 0) << warn.err;
  EXPECT_NE(warn.err.find("warning: gravity stage: not at rest after 20 steps"), std::string::npos) << warn.err;
  EXPECT_EQ(rows(dir / "warn" / "gravity_stage.csv").size(), 20u);
  // a body that falls out through an outflow face while settling
  std::ofstream(dir / "outflow.yaml")
      << "dimension: 2\n"
         "grid: {extent: [1, 1], cell_size: 0.1, boundary: {y_min: outflow}}\n"
         "materials: {soil: {model: linear_elastic, density: 2000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}\n"
         "bodies: [{name: block, material: soil, shape: {type: box, min: [0.3, 0.1], max: [0.7, 0.4]}}]\n"
         "solver: {cfl: 0.5, end_time: 0.01, gravity: [0, -10], gravity_stage: {}}\n";
  const auto out = mpm("run " + (dir / "outflow.yaml").string() + " -o " + (dir / "outflow").string(), dir);
  EXPECT_EQ(out.status, 2) << out.err;
  EXPECT_NE(out.err.find((dir / "outflow.yaml").string() + ":5:"), std::string::npos) << out.err;
  EXPECT_NE(out.err.find("particles left through the outflow face y_min while the bodies settled under gravity"),
            std::string::npos)
      << out.err;
  EXPECT_FALSE(fs::exists(dir / "outflow"));
  // `mpm check` does not run the stage
  EXPECT_EQ(mpm("check " + (dir / "stop.yaml").string(), dir).status, 0);
  fs::remove_all(dir);
}

}  // namespace
