#pragma once
/// \file csv_log.hpp
/// A small CSV table written as the run goes (one row per output frame: time, energies...).

#include <filesystem>
#include <string>
#include <vector>

#include "mpm/io/continued_file.hpp"

namespace mpm::io {

/// A CSV table: a header line of column names, then one line per row, numbers in full precision
/// (%.17g, always with '.' as decimal point). Rows are kept in memory and the whole file is
/// rewritten atomically by the constructor (header only) and by each append(), so the file on disk
/// is always complete.
class CsvLog {
 public:
  /// Writes the header to `path` (replacing any previous file). Throws std::invalid_argument if
  /// `columns` is empty.
  CsvLog(std::filesystem::path path, std::vector<std::string> columns);
  /// Continues the table of a checkpointed run (continued_file.hpp): `path` becomes the first from.bytes
  /// bytes of from.path, whose rows are read back. Throws std::runtime_error naming the file when they
  /// cannot be, or when its header is not `columns`.
  CsvLog(std::filesystem::path path, std::vector<std::string> columns, const FileMark& from);

  /// The table's length on disk now, for a checkpoint.
  FileMark mark() const { return mark_file(path_); }

  /// Adds a row and rewrites the file. Throws std::invalid_argument, and keeps the table unchanged,
  /// if row.size() != the number of columns or if a value is not finite.
  void append(const std::vector<double>& row);

  /// Where the table is written.
  const std::filesystem::path& path() const { return path_; }

 private:
  void write() const;

  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
};

}  // namespace mpm::io
