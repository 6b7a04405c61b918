#pragma once
// The readers of the core's scene sections (docs/scene-reference.md), one file each, called by parse_scene()
// (scene_loader.cpp) in this order. Each reads through the one YAML reader (mpm/io/yaml_reader.hpp).

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "mpm/scene/scene.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm {
struct MaterialModel;
}

namespace mpm::sections {

using io::Range;
using io::YamlMap;
using io::YamlReader;
using io::YamlValue;

/// Axis names for messages, in the order x, y, z.
inline constexpr const char* axis_names[3] = {"x", "y", "z"};
/// Relative tolerance of "extent / cell_size is an integer" and of "the body lies inside the grid".
inline constexpr double geometric_tolerance = 1e-9;

inline bool contains(const std::vector<std::string>& items, const std::string& item) {
  return std::find(items.begin(), items.end(), item) != items.end();
}

/// `dimension:` (grid_section.cpp).
int read_dimension(const io::YamlReader& reader, const io::YamlMap& top);
/// `grid:` with its `boundary:` (grid_section.cpp).
GridDescription read_grid(const io::YamlReader& reader, const io::YamlValue& value, int dimension);
/// `grid.coordinates` and the axisymmetric rules (axisymmetric_grid.cpp): called by read_grid once the origin and
/// the boundary are read; holds the radial velocity on the axis face.
void read_coordinates(const io::YamlReader& reader, const io::YamlMap& map, int dimension, GridDescription& grid);
/// `materials:`, checked against the registered models (materials_section.cpp).
std::map<std::string, MaterialDescription> read_materials(const io::YamlReader& reader, const io::YamlValue& value);
/// `materials.NAME.failure` of `material`, whose model is `model` (failure_block.cpp).
FailureCriteria read_failure(const io::YamlReader& reader, const io::YamlValue& value,
                             const MaterialDescription& material, const MaterialModel& model);
/// `bodies:`, with their shapes (bodies_section.cpp); needs the grid and the materials.
std::vector<BodyDescription> read_bodies(const io::YamlReader& reader, const io::YamlValue& value,
                                         const SceneDescription& scene);
/// `sets:` (sets_section.cpp); needs the bodies.
std::vector<SetDescription> read_sets(const io::YamlReader& reader, const io::YamlValue& value,
                                      const SceneDescription& scene);
/// `conditions:` (sets_section.cpp); needs the sets.
std::vector<SetConditionDescription> read_conditions(const io::YamlReader& reader, const io::YamlValue& value,
                                                     const SceneDescription& scene);
/// `solver:` (solver_section.cpp); needs the grid.
SolverDescription read_solver(const io::YamlReader& reader, const io::YamlValue& value, const SceneDescription& scene);
/// `output:` (output_section.cpp); needs the grid and the bodies (its histories name them).
OutputDescription read_output(const io::YamlReader& reader, const io::YamlValue& value, const SceneDescription& scene);
/// `output.histories:` (histories_section.cpp); `output_interval` is the default interval.
std::vector<HistoryDescription> read_histories(const io::YamlReader& reader, const io::YamlValue& value,
                                               const SceneDescription& scene, double output_interval);

}  // namespace mpm::sections
