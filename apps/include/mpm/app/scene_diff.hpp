#pragma once
/// \file scene_diff.hpp
/// What differs between the scene a checkpoint was written with and the scene a restart is given, key by
/// key, and whether each difference is a run-control key that a fork may change (docs/scene-reference.md,
/// "Restart and fork"): the keys the sections' specs mark (io::KeySpec::run_control, scene_keys.hpp: everything
/// under output; the modules' keys, e.g. contact's plane velocities), and solver.end_time, solver.cfl and the
/// prescribed velocities of grid.boundary.

#include <string>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace mpm::app {

struct SceneDifference {
  std::string key;       ///< dotted path: "materials.steel.yield_stress", "bodies[0].shape.radius"
  SourceLocation where;  ///< in the new scene; in the checkpoint's scene (file "checkpoint") for a removed key
  std::string was, now;  ///< the values as YAML text ("(absent)" when missing)
  bool run_control = false;
};

/// The differences between the YAML texts `saved` (the checkpoint's scene) and `current` (file
/// `current_file`), in the order of the keys; numbers that are equal in value are equal ("1e3" and "1000").
/// Throws SceneError when `saved` is not YAML.
std::vector<SceneDifference> scene_differences(const std::string& saved, const std::string& current,
                                               const std::string& current_file);

/// Whether `key` (a dotted path) is a run-control key (see the file comment).
bool is_run_control_key(const std::string& key);

}  // namespace mpm::app
