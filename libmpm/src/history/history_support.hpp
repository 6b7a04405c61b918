#pragma once
// What the history kinds (one file each in this folder) share: reading a body name, an axis and a box through
// the one YAML reader, the component names of an output field, and the errors of the build stage.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mpm/history/history_kind.hpp"
#include "mpm/output/output_fields.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::history {

using io::YamlMap;
using io::YamlReader;
using io::YamlValue;

/// A kind from its parts (the makers are one template's instantiations, `make<1>, make<2>, make<3>`).
inline HistoryKind history_kind(std::string type, std::string description, std::vector<std::string> keys,
                                HistoryParser parse, HistoryMaker<1> make_1d, HistoryMaker<2> make_2d,
                                HistoryMaker<3> make_3d, HistoryFields fields = nullptr) {
  HistoryKind k;
  k.type = std::move(type);
  k.description = std::move(description);
  k.keys = std::move(keys);
  k.parse = parse;
  k.fields = fields;
  k.make_1d = make_1d;
  k.make_2d = make_2d;
  k.make_3d = make_3d;
  return k;
}

/// The core's kinds, registered by history_kind.cpp (one file each).
HistoryKind probe_kind();
HistoryKind reaction_kind();
HistoryKind energy_kind();
HistoryKind extent_kind();
HistoryKind particle_kind();
HistoryKind force_kind();

/// An axis-aligned box of the scene (`{min: [...], max: [...]}`), m; coordinates beyond the dimension are 0.
struct Box {
  std::array<double, 3> min{0, 0, 0}, max{0, 0, 0};
  template <int Dim>
  bool contains(const VecU<Dim>& x) const {
    for (int d = 0; d < Dim; ++d)
      if (!(x[d] >= min[d] && x[d] <= max[d])) return false;
    return true;
  }
};

/// `body: NAME`: the index of one of the scene's bodies.
int read_body(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene);
/// `set: NAME`: the index of one of the scene's particle sets (`sets:`).
int read_set(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene);
/// `fields: [...]`: output field names with point values (every selectable one but `domains`), each once.
std::vector<std::string> read_point_fields(const YamlReader& reader, const YamlValue& value);
/// `axis: x | y | z` (only the scene's axes).
int read_axis(const YamlReader& reader, const YamlValue& value, int dimension);
/// `{min: [...], max: [...]}` with min < max on every axis, overlapping the grid box.
Box read_box(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene);
/// A point of `dimension` coordinates inside the grid box (`what` names it in the message).
std::array<double, 3> read_point_in_grid(const YamlReader& reader, const YamlValue& value,
                                         const SceneDescription& scene, const char* what);

/// Suffixes of the components of `field` as a history writes them: "" (scalar), _x _y (_z) (a vector, only
/// the run's axes), _xx _yy _zz _xy _yz _xz (symmetric), _xx _xy ... _zz (3x3). Component c is at offset c of
/// a particle's values in the field's padded layout (a vector's unused axes are the last ones).
std::vector<std::string> component_suffixes(const OutputField& field, int dim);

/// A SceneError at the history's entry: "FILE:LINE:COLUMN: output.histories[i].KEY: message".
[[noreturn]] void fail(const HistoryDescription& history, const std::string& key, const std::string& message);

/// The bodies a history on `fields` reads: `body` alone (each field must be defined on it), or every body on
/// which all the fields are defined (at least one). Throws SceneError at the history's `fields` key.
template <int Dim>
std::vector<int> bodies_defining(const HistoryDescription& history, const std::vector<const OutputField*>& fields,
                                 int body, const std::vector<Body<Dim>>& bodies);

}  // namespace mpm::history
