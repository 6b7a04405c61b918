// The registry of history kinds (history_kind.hpp): the core's six, then whatever modules register; and the
// pieces every kind shares (the output-field cache, units, building a scene's histories).
#include "mpm/history/history_kind.hpp"

#include <deque>

#include "history_support.hpp"
#include "mpm/core/kind_table.hpp"
#include "mpm/output/output_fields.hpp"

namespace mpm {
namespace {

/// The core's kinds, then the modules' (core/kind_table.hpp), found by their `type`.
KindTable<HistoryKind, &HistoryKind::type>& history_table() {
  static KindTable<HistoryKind, &HistoryKind::type> t{
      std::deque<HistoryKind>{history::probe_kind(), history::reaction_kind(), history::energy_kind(),
                              history::extent_kind(), history::particle_kind(), history::force_kind()}};
  return t;
}

}  // namespace

void register_history_kind(HistoryKind kind) { history_table().add(std::move(kind)); }

const HistoryKind* find_history_kind(std::string_view type) { return history_table().find(type); }

std::vector<std::string> history_kind_names() { return history_table().names(); }

std::vector<std::string> history_output_fields(const OutputDescription& output) {
  std::vector<std::string> fields;
  for (const auto& h : output.histories)
    if (const HistoryKind* kind = find_history_kind(h.type); kind && kind->fields)
      for (auto& f : kind->fields(h.spec))
        if (std::find(fields.begin(), fields.end(), f) == fields.end()) fields.push_back(std::move(f));
  return fields;
}

std::string extensive_unit(const std::string& unit, int dim, Coordinates coordinates) {
  if (dim == 3 || coordinates == Coordinates::axisymmetric) return unit;
  return unit + (dim == 2 ? "/m" : "/m^2");
}

std::string column_name(const std::string& name, const std::string& unit) { return name + " [" + unit + "]"; }

template <int Dim>
const std::vector<double>& OutputFieldCache<Dim>::values(const std::string& name, int b) {
  const auto key = std::make_pair(name, b);
  auto it = values_.find(key);
  if (it == values_.end()) {
    it = values_.emplace(key, std::vector<double>{}).first;
    append_output_field<Dim>(name, sim_.bodies()[static_cast<std::size_t>(b)], it->second);
  }
  return it->second;
}

template <int Dim>
std::vector<BuiltHistory<Dim>> build_histories(const SceneDescription& scene, Simulation<Dim>& sim,
                                               std::vector<std::string>& warnings) {
  std::vector<BuiltHistory<Dim>> built;
  for (const auto& h : scene.output.histories) {
    const HistoryKind* kind = find_history_kind(h.type);
    if (!kind || !kind->template maker<Dim>())
      history::fail(h, "type", "history type '" + h.type + "' is not available in " + std::to_string(Dim) + "D");
    built.push_back({&h, kind->template maker<Dim>()(h, scene, sim, warnings)});
  }
  return built;
}

template class OutputFieldCache<1>;
template class OutputFieldCache<2>;
template class OutputFieldCache<3>;
template std::vector<BuiltHistory<1>> build_histories<1>(const SceneDescription&, Simulation<1>&,
                                                         std::vector<std::string>&);
template std::vector<BuiltHistory<2>> build_histories<2>(const SceneDescription&, Simulation<2>&,
                                                         std::vector<std::string>&);
template std::vector<BuiltHistory<3>> build_histories<3>(const SceneDescription&, Simulation<3>&,
                                                         std::vector<std::string>&);

}  // namespace mpm
