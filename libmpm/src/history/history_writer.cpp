#include "mpm/history/history_writer.hpp"

#include <algorithm>
#include <optional>
#include <span>

#include "mpm/core/due_time.hpp"

namespace mpm {

template <int Dim>
HistoryWriter<Dim>::HistoryWriter(const std::filesystem::path& directory, std::vector<BuiltHistory<Dim>> built,
                                  const StateArchive* restart, bool writes_files) {
  if (built.empty()) return;
  if (writes_files) std::filesystem::create_directories(directory);
  for (auto& b : built) {
    std::vector<std::string> columns{"time [s]", "step"};
    for (auto& c : b.history->columns()) columns.push_back(std::move(c));
    const Real interval = b.description->interval;
    const std::filesystem::path file = directory / (b.description->name + ".csv");
    if (!restart || !restart->contains(state_prefix(b.description->name) + "next_time")) {  // new in a fork
      entries_.push_back({std::move(b),
                          columns,
                          writes_files ? std::optional<io::CsvLog>(io::CsvLog(file, columns)) : std::nullopt,
                          interval,
                          0,
                          -1,
                          false,
                          {},
                          {}});
      continue;
    }
    const std::string prefix = state_prefix(b.description->name);
    std::optional<io::CsvLog> csv;
    if (writes_files) csv.emplace(file, columns, io::load_mark(*restart, prefix + "csv"));
    b.history->restore_state(*restart, prefix + "history/");
    entries_.push_back({std::move(b),
                        columns,
                        std::move(csv),
                        interval,
                        restart->number(prefix + "next_time"),
                        restart->number(prefix + "last_written"),
                        restart->integer(prefix + "started") != 0,
                        restart->values<double>(prefix + "last_row"),
                        {}});
  }
}

template <int Dim>
std::string HistoryWriter<Dim>::state_prefix(const std::string& name) {
  return "histories/" + name + "/";
}

template <int Dim>
void HistoryWriter<Dim>::save_state(StateArchive& archive) const {
  for (const auto& e : entries_) {
    const std::string prefix = state_prefix(e.built.description->name);
    if (e.csv) io::save_mark(archive, prefix + "csv", e.csv->mark());
    archive.put_number(prefix + "next_time", e.next_time);
    archive.put_number(prefix + "last_written", e.last_written);
    archive.put_integer(prefix + "started", e.started ? 1 : 0);
    archive.put_values<double>(prefix + "last_row", std::span<const double>(e.last_row));
    e.built.history->save_state(archive, prefix + "history/");
  }
}

template <int Dim>
void HistoryWriter<Dim>::write_rows(const Simulation<Dim>& sim, bool all) {
  const Real tolerance = 1e-9 * std::max<Real>(1, sim.settings().end_time);
  std::optional<OutputFieldCache<Dim>> cache;  // made at the first history due: nothing when none is
  for (auto& e : entries_) {
    if (e.last_written == sim.time()) continue;
    const bool due = all || !e.started || (e.interval > 0 && sim.time() >= e.next_time - tolerance);
    if (!due) continue;
    if (!cache) cache.emplace(sim);
    std::vector<double> row{sim.time(), static_cast<double>(sim.step())};
    e.built.history->sample(sim, *cache, row);
    if (e.csv) e.csv->append(row);
    if (keep_rows_) e.rows.insert(e.rows.end(), row.begin(), row.end());
    e.last_row = std::move(row);
    e.started = true;
    e.last_written = sim.time();
    if (e.interval > 0) e.next_time = next_due_time(e.next_time, e.interval, sim.time() + tolerance);
  }
}

template <int Dim>
void HistoryWriter<Dim>::write_if_due(const Simulation<Dim>& sim) {
  write_rows(sim, false);
}

template <int Dim>
void HistoryWriter<Dim>::write(const Simulation<Dim>& sim) {
  write_rows(sim, true);
}

template class HistoryWriter<1>;
template class HistoryWriter<2>;
template class HistoryWriter<3>;

}  // namespace mpm
