// `output.histories:` (docs/scene-reference.md#histories): a list of entries, each with a name (its CSV file),
// a type (a kind of the history registry, history/history_kind.hpp, which parses the entry's own keys) and an
// interval.
#include <fmt/format.h>

#include <cctype>

#include "mpm/history/history_kind.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/spec_map.hpp"
#include "sections.hpp"

namespace mpm {

const std::vector<io::KeySpec>& history_keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> keys{
      {.name = "name",
       .type = KeyType::name,
       .required = true,
       .description = "the file is `NAME.csv`",
       .allowed_text = "letters, digits, `_`, `-`, `.`; unique; not `energy` (taken by energy.csv)"},
      {.name = "type",
       .type = KeyType::choice,
       .required = true,
       .description = "the kind of history (table below)",
       .allowed_text = "a registered history kind"},
      {.name = "interval",
       .type = KeyType::number,
       .unit = "s",
       .range = io::Range::above(0),
       .absent = "`output.interval`",
       .description = "time between rows; this or `output.interval` must be given"},
  };
  return keys;
}

namespace sections {
namespace {

/// A history's name becomes a file name: letters, digits, '_', '-' and '.', not the audit's `energy`.
void check_history_name(const YamlReader& reader, const YamlValue& value, const std::string& name) {
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
      reader.fail(value, fmt::format("'{}' cannot name a file: use letters, digits, '_', '-' and '.'", name));
  if (name == "energy") reader.fail(value, "'energy' is taken by the conservation audit energy.csv");
}

}  // namespace

std::vector<HistoryDescription> read_histories(const YamlReader& reader, const YamlValue& value,
                                               const SceneDescription& scene, double output_interval) {
  std::vector<HistoryDescription> histories;
  for (const auto& item : reader.list(value, std::nullopt, "histories")) {
    const io::SpecMap entry(reader, item, history_keys(), io::SpecMap::AllowLater{});
    HistoryDescription h;
    h.where = reader.location(item.mark);
    h.path = item.path;
    const YamlValue name = entry.required("name");
    h.name = reader.name(name);
    check_history_name(reader, name, h.name);
    for (const auto& other : histories)
      if (other.name == h.name)
        reader.fail(name, fmt::format("history name '{}' is used twice (line {}); each names its CSV file", h.name,
                                      other.where.line));
    const YamlValue type = entry.required("type");
    h.type = reader.choice(type, history_kind_names());
    const HistoryKind& kind = *find_history_kind(h.type);
    entry.allow(kind.keys, "key", " for a history of type " + h.type);
    if (const auto interval = entry.optional_number("interval")) {
      h.interval = *interval;
    } else {
      h.interval = output_interval;
      if (!(h.interval > 0))
        reader.fail(item,
                    "give the history an interval (s), or output.interval: with neither it would have only a "
                    "first and a last row");
    }
    h.spec = kind.parse(reader, entry.map(), scene);
    histories.push_back(std::move(h));
  }
  return histories;
}

}  // namespace sections
}  // namespace mpm
