#pragma once
/// \file history_writer.hpp
/// Writes the scene's histories (`output.histories`) during a run: one CSV per history, NAME.csv beside the
/// frames, a header `time [s],step,<the history's columns with units>` and one row every `interval` (the
/// first at the start, the last at the end), through io::CsvLog (each row appended and flushed: the file on
/// disk holds every row written, and a history written every step costs time linear in the steps). Histories
/// due at the same time share one output-field cache. A scene without histories builds nothing here.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mpm/history/history_kind.hpp"
#include "mpm/io/csv_log.hpp"

namespace mpm {

template <int Dim>
class HistoryWriter {
 public:
  /// Writes the header of each history's CSV into `directory` (created if there is any history). Build the
  /// histories first (build_histories: it throws SceneError for a bad one), so that a refused scene writes nothing.
  /// With `restart` (a checkpoint's state, run_checkpoints.hpp), each CSV is continued from its length at the
  /// checkpoint (continued_file.hpp) and the schedules and the histories' own state are restored. Without
  /// `writes_files` (every rank but 0 of a distributed run) the histories are sampled alike (their sums are
  /// collective) but no file is touched.
  HistoryWriter(const std::filesystem::path& directory, std::vector<BuiltHistory<Dim>> histories,
                const StateArchive* restart = nullptr, bool writes_files = true);
  /// The CSVs' lengths, the schedules and the histories' state, as entries histories/NAME/... of a checkpoint.
  void save_state(StateArchive& archive) const;
  /// Writes a row of every history whose next time has come (of all at the first call).
  void write_if_due(const Simulation<Dim>& sim);
  /// Writes a row of every history now, unless it was written at this time (the last row of a run).
  void write(const Simulation<Dim>& sim);
  bool empty() const { return entries_.empty(); }
  std::size_t size() const { return entries_.size(); }
  /// History k's scene entry, its CSV columns (with `time [s]` and `step`) and the last row written.
  const HistoryDescription& description(std::size_t k) const { return *entries_[k].built.description; }
  const std::vector<std::string>& columns(std::size_t k) const { return entries_[k].columns; }
  const std::vector<double>& last_row(std::size_t k) const { return entries_[k].last_row; }
  /// Keep every row written from now on in memory (rows()); off by default.
  void keep_rows(bool keep) { keep_rows_ = keep; }
  /// History k's rows kept so far, row after row, columns(k).size() values each (no data: io::no_data()).
  const std::vector<double>& rows(std::size_t k) const { return entries_[k].rows; }

 private:
  struct Entry {
    BuiltHistory<Dim> built;
    std::vector<std::string> columns;
    std::optional<io::CsvLog> csv;  ///< none on a rank that does not write
    Real interval = 0;
    Real next_time = 0;
    Real last_written = -1;
    bool started = false;
    std::vector<double> last_row;
    std::vector<double> rows;  ///< with keep_rows: every row since then
  };
  void write_rows(const Simulation<Dim>& sim, bool all);
  static std::string state_prefix(const std::string& name);

  std::vector<Entry> entries_;
  bool keep_rows_ = false;
};

}  // namespace mpm
