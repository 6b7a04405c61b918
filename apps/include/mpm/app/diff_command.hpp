#pragma once
/// \file diff_command.hpp
/// `mpm diff RUN_A RUN_B [--tolerance REL] [--absolute ABS] [--time-tolerance T]`: compares two output directories
/// for regression checks. Every .pvd series of RUN_A frame by frame (the points, every point field; particles
/// matched by body and id when both runs write them), and every CSV (energy.csv, the histories, the contact forces)
/// column by column; prints per field the largest absolute and relative difference and the first frame (or row)
/// that differs. A value differs when |a - b| > max(ABS, REL * the largest |a| of that field in that frame); by
/// default (0, 0) only identical values are equal. Frames, and the rows of a CSV whose first column is the time,
/// are paired by time, not by number: two times are the same when they differ by at most T (default 1e-6) times
/// the finer output interval of the two (the median gap between a run's consecutive times); the times one run has
/// and the other has not are listed, and make the runs different.

#include <filesystem>
#include <iosfwd>

namespace mpm::app {

struct DiffOptions {
  std::filesystem::path a, b;
  double relative = 0;           ///< --tolerance
  double absolute = 0;           ///< --absolute
  double time_tolerance = 1e-6;  ///< --time-tolerance: of the finer output interval
};

/// Exit status: 0 equal within the tolerance, 1 different (times without a partner included), 2 bad input (a directory
/// missing, no output in it, an unreadable file).
int diff_command(const DiffOptions& options, std::ostream& out, std::ostream& err);

}  // namespace mpm::app
