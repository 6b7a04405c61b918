#include "mpm/history/history_writer.hpp"

#include <algorithm>
#include <optional>

namespace mpm {

template <int Dim>
HistoryWriter<Dim>::HistoryWriter(const std::filesystem::path& directory, std::vector<BuiltHistory<Dim>> built) {
  if (built.empty()) return;
  std::filesystem::create_directories(directory);
  for (auto& b : built) {
    std::vector<std::string> columns{"time [s]", "step"};
    for (auto& c : b.history->columns()) columns.push_back(std::move(c));
    const Real interval = b.description->interval;
    const std::filesystem::path file = directory / (b.description->name + ".csv");
    entries_.push_back({std::move(b), columns, io::CsvLog(file, columns), interval, 0, -1, false, {}});
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
    e.csv.append(row);
    e.last_row = std::move(row);
    e.started = true;
    e.last_written = sim.time();
    if (e.interval > 0)
      while (e.next_time <= sim.time() + tolerance) e.next_time += e.interval;
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
