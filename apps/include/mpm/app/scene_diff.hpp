#pragma once
/// \file scene_diff.hpp
/// What differs between the scene a checkpoint was written with and the scene a restart is given, key by
/// key, and whether a fork may change each (docs/scene-reference.md, "Restart and fork"), as the specs declare it
/// (io::KeySpec::run_control and fork_refusal, scene_keys.hpp; the materials' parameters, material_fork_rules):
/// run control (output, end time, time step), boundary conditions, material parameters, loads and solver options
/// that keep the state's layout; not the grid, the bodies' particles or what fixes the layout of the state.

#include <string>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace mpm::app {

struct SceneDifference {
  std::string key;           ///< dotted path: "materials.steel.yield_stress", "bodies[0].shape.radius"
  SourceLocation where;      ///< in the new scene; in the checkpoint's scene (file "checkpoint") for a removed key
  std::string was, now;      ///< the values as YAML text ("(absent)" when missing)
  bool run_control = false;  ///< a fork may change it
  std::string refusal;       ///< when it may not: why ("the grid is the checkpoint's")
};

/// The reason of a refused key whose spec declares none (a module's section that declares no fork rules).
inline constexpr const char* undeclared_refusal = "its spec does not declare that a fork may change it";

/// The differences between the YAML texts `saved` (the checkpoint's scene) and `current` (file
/// `current_file`), in the order of the keys; numbers that are equal in value are equal ("1e3" and "1000").
/// Throws SceneError when `saved` is not YAML.
std::vector<SceneDifference> scene_differences(const std::string& saved, const std::string& current,
                                               const std::string& current_file);

/// Whether a fork may change `key` (a dotted path; see the file comment).
bool is_run_control_key(const std::string& key);

}  // namespace mpm::app
