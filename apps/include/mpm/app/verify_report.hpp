#pragma once
/// \file verify_report.hpp
/// What `mpm verify` found (verify_command.hpp) and how it is written: the Markdown report, the table of runs
/// for the plot, and the plot itself (a Python script written beside them and run with /usr/bin/python3 and
/// matplotlib).

#include <array>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "mpm/app/solution_verification.hpp"

namespace mpm::app {

struct VerifyRun {
  std::array<int, 3> cells{1, 1, 1};
  double h = 0;  ///< representative cell size (geometric mean over the axes), m
  long long particles = 0, steps = 0;
  double seconds = 0;               ///< wall time of the run (building and stepping)
  std::vector<double> values;       ///< one per quantity
  std::vector<double> body_masses;  ///< kg (per unit length in 2D, per area in 1D), per body at t = 0
};

struct VerifyQuantity {
  std::string name;             ///< as given: HISTORY.COLUMN[@TIME]
  std::string column;           ///< the CSV column, with its unit
  std::optional<double> time;   ///< s; empty: at the end
  std::optional<double> start;  ///< s; the quantity is the change since then
  ConvergenceResult result;
};

struct VerifyReport {
  std::string scene_file;
  std::string command;  ///< the command line, for the record
  int dimension = 2;
  double ratio = 2;
  std::vector<VerifyRun> runs;  ///< coarsest first
  std::vector<VerifyQuantity> quantities;
  std::string stopped;                ///< why fewer runs than asked finished (the guard's message), or empty
  std::vector<std::string> warnings;  ///< what makes the runs differ besides the resolution (a body's mass)
};

/// Writes DIR/verify.md, DIR/verify_runs.csv and, with `plot`, DIR/plot_verify.py and DIR/verify.png (the
/// report says when the plot could not be made). Prints a summary to `out`.
void write_verify_report(const std::filesystem::path& dir, const VerifyReport& report, bool plot, std::ostream& out);

}  // namespace mpm::app
