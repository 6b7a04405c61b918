#pragma once
/// \file output_scan.hpp
/// Reads back everything a run wrote (every .vtu through VTK's reader, every .csv as text), so that the
/// stability cases assert on the files a user opens: no NaN or Inf anywhere (DESIGN.md: "never write NaN into
/// an output file silently"), the smallest det F of the frames, the energy history.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace mpm::verification {

struct OutputScan {
  int vtu_files = 0;
  int csv_files = 0;             ///< energy.csv and any table a module writes (contact forces)
  long long values = 0;          ///< numbers read from the .vtu files (point coordinates and arrays)
  std::vector<std::string> bad;  ///< "file: array" for every non-finite value found (or unreadable file)
  double min_det_F = 0;          ///< smallest det F over the frames ("deformation_gradient"; 0 if absent)
  double max_det_F = 0;          ///< largest det F over the frames (0 if absent)
  double max_abs_stress = 0;     ///< largest |component| of "stress" over the frames, Pa
  std::vector<std::map<std::string, double>> energy;  ///< energy.csv, one map per row (column -> value)
  bool all_finite() const { return bad.empty(); }
  /// Total energy of the last row relative to the first, and the largest growth over the rows.
  double energy_change() const;
  double max_energy_growth() const;
  /// "N frames, all M values finite", or the first non-finite value's file and array (for a case's report).
  std::string finite_text() const;
};

/// Scans the directory `dir` (not recursively). A .vtu that VTK cannot read counts as bad.
OutputScan scan_output(const std::filesystem::path& dir);

}  // namespace mpm::verification
