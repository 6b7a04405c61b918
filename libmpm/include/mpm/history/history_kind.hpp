#pragma once
/// \file history_kind.hpp
/// The one registry of history kinds (`output.histories[].type`): probe, reaction, energy, extent, and any a
/// module registers. A kind is a parser (through the one YAML reader, io/yaml_reader.hpp, so its errors read
/// like every other section's) and a maker per dimension; each lives in one small file of src/history/.
/// The loader's list of valid types, the builder and `mpm verify` all read this table.

#include <any>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mpm/history/history.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm {

namespace io {
class YamlReader;
class YamlMap;
}  // namespace io

/// Reads the kind's own keys of one entry (`name`, `type` and `interval` are read by the caller) and returns
/// its description (stored in HistoryDescription::spec). Throws SceneError naming file, line and key.
using HistoryParser = std::any (*)(const io::YamlReader& reader, const io::YamlMap& entry,
                                   const SceneDescription& scene);
/// The history for a built simulation; may add a module to it (reactions accumulate every step). Throws
/// SceneError (at `history.where`) for what needs the built bodies (a field the body's material does not
/// define, a plane no module knows); adds to `warnings` what is suspicious but allowed (an empty region).
template <int Dim>
using HistoryMaker = std::unique_ptr<History<Dim>> (*)(const HistoryDescription& history, const SceneDescription& scene,
                                                       Simulation<Dim>& sim, std::vector<std::string>& warnings);
/// The output fields (output_fields.hpp) a history reads, so that the builder prepares them on the bodies.
using HistoryFields = std::vector<std::string> (*)(const std::any& spec);

struct HistoryKind {
  std::string type;               ///< the scene's `type:`
  std::string description;        ///< one line for the scene reference
  std::vector<std::string> keys;  ///< the keys it reads besides name, type and interval
  HistoryParser parse = nullptr;
  HistoryFields fields = nullptr;  ///< null: reads no output field
  HistoryMaker<1> make_1d = nullptr;
  HistoryMaker<2> make_2d = nullptr;
  HistoryMaker<3> make_3d = nullptr;

  template <int Dim>
  HistoryMaker<Dim> maker() const {
    if constexpr (Dim == 1) return make_1d;
    if constexpr (Dim == 2) return make_2d;
    if constexpr (Dim == 3) return make_3d;
  }
};

/// Adds (or replaces) the kind with this type. The core's kinds are registered when the table is first read.
void register_history_kind(HistoryKind kind);
/// The kind with this type, or nullptr. The pointer stays valid.
const HistoryKind* find_history_kind(std::string_view type);
/// The registered types, in registration order (the core's first).
std::vector<std::string> history_kind_names();

/// The output fields every history of `output` reads (to prepare them on the bodies, like output.fields).
std::vector<std::string> history_output_fields(const OutputDescription& output);

/// A built history with its scene entry.
template <int Dim>
struct BuiltHistory {
  const HistoryDescription* description = nullptr;  ///< points into the scene it was built from
  std::unique_ptr<History<Dim>> history;
};
/// Builds every history of scene.output.histories on `sim` (adding the modules they need). Throws SceneError.
template <int Dim>
std::vector<BuiltHistory<Dim>> build_histories(const SceneDescription& scene, Simulation<Dim>& sim,
                                               std::vector<std::string>& warnings);

}  // namespace mpm
