#pragma once
/// \file scene_section.hpp
/// Top-level scene keys owned by optional modules (e.g. `thermal:`). A module registers a parser for its
/// key; the scene loader accepts the key only when a parser is registered, hands it the YAML node (whose
/// marks give the lines for SceneError) once the core sections are read, and stores what it returns in
/// SceneDescription::sections under the key. The core never looks inside.

#include <yaml-cpp/yaml.h>

#include <any>
#include <functional>
#include <string>
#include <vector>

#include "mpm/scene.hpp"

namespace mpm {

/// Reads and checks the section `node` of the scene `scene` (core sections already read; `scene.file` names
/// the file for messages). Throws SceneError naming file, line and key.
using SceneSectionParser = std::function<std::any(const YAML::Node& node, const SceneDescription& scene)>;

/// Registers (or replaces) the parser of the top-level key `key`. Call before loading scenes.
void register_scene_section(const std::string& key, SceneSectionParser parser);
/// The registered keys, in registration order.
std::vector<std::string> scene_section_keys();

}  // namespace mpm
