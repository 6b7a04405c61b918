#pragma once
/// \file csv_log.hpp
/// A small CSV table written as the run goes (one row per output frame: time, energies...).

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mpm/io/continued_file.hpp"

namespace mpm::io {

/// "No data" in a row: a quiet NaN with a payload of its own, written as an empty cell (a probe whose region
/// holds no particle, a followed particle that has eroded). Any other non-finite value is still refused, so a
/// NaN computed by mistake is not hidden as an empty cell.
inline constexpr std::uint64_t no_data_bits = 0x7ff8'0000'00da'7a00ULL;
inline double no_data() { return std::bit_cast<double>(no_data_bits); }
inline bool is_no_data(double v) { return std::bit_cast<std::uint64_t>(v) == no_data_bits; }

/// A CSV table: a header line of column names, then one line per row, numbers in full precision
/// (%.17g, always with '.' as decimal point). The constructor writes the header atomically (replacing any
/// previous file); each append() adds its line, formatted first and written with one flushed write, at the
/// end of the open file, so that the file on disk holds every row appended so far. (Rewriting the whole
/// file per row, as this class once did, made a history written every step quadratic in the run length.)
class CsvLog {
 public:
  /// Writes the header to `path` (replacing any previous file). Throws std::invalid_argument if
  /// `columns` is empty.
  CsvLog(std::filesystem::path path, std::vector<std::string> columns);
  /// Continues the table of a checkpointed run (continued_file.hpp): `path` becomes the first from.bytes
  /// bytes of from.path, whose rows are checked (numbers or empty cells, one per column) and then appended to. Throws
  /// std::runtime_error naming the file when they cannot be, or when its header is not `columns`.
  CsvLog(std::filesystem::path path, std::vector<std::string> columns, const FileMark& from);

  /// The table's length on disk now, for a checkpoint.
  FileMark mark() const { return mark_file(path_); }

  /// Appends a row to the file. Throws std::invalid_argument, and writes nothing, if row.size() != the
  /// number of columns or if a value is not finite (but no_data(), written as an empty cell); std::runtime_error
  /// if the file cannot be written.
  void append(const std::vector<double>& row);

  /// Where the table is written.
  const std::filesystem::path& path() const { return path_; }
  /// The header's column names.
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::ofstream out_;  ///< the file after its header, in append mode
};

}  // namespace mpm::io
