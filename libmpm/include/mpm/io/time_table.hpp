#pragma once
/// \file io/time_table.hpp
/// A time history read from a CSV file (a ground motion: `grid.boundary.FACE: {type: absorbing, input_velocity:
/// {file: F}}`, docs/scene-reference.md): a header line naming the columns, the first `t` (s), the others from a
/// given list (`vx`, `vy`, `vz`), then one row of numbers per time, times strictly increasing. Blank lines and lines
/// starting with `#` are skipped. Between rows the values are interpolated linearly; before the first row and after
/// the last they are the nearest row's (end a record with a row of zeros to stop the motion).

#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace mpm::io {

/// A time-history file that cannot be read or holds a bad value; what() is "FILE: message" or, for one line,
/// "FILE:LINE: message".
class TimeTableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct TimeTable {
  std::filesystem::path file;
  std::vector<double> time;                   ///< s, strictly increasing
  std::vector<std::array<double, 3>> values;  ///< per row, per slot of `columns` given to read_time_table (0 if absent)
  /// The values at time t (linear between rows, the nearest row's outside them).
  std::array<double, 3> at(double t) const;
};

/// Reads `file`; `columns` are the names the value columns may have, in slot order (e.g. {"vx", "vy"}): a header
/// may list any of them, in any order, after `t`; a slot not listed is 0. Throws TimeTableError naming the file and
/// line for a file that cannot be opened, a header whose first column is not `t` or that names an unknown or repeated
/// column, a row with another number of values than the header, a value that is not a finite number, times that do
/// not increase, or no row.
TimeTable read_time_table(const std::filesystem::path& file, const std::vector<std::string>& columns);

}  // namespace mpm::io
