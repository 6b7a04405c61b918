#pragma once
/// \file scene_loader.hpp
/// Reads a YAML scene file (format: docs/scene-reference.md) into a SceneDescription, checking every
/// key and value. Any problem is reported as a SceneError pointing at FILE:LINE:COLUMN and the key.

#include <filesystem>
#include <string>

#include "mpm/scene/scene.hpp"
#include "mpm/scene/scene_error.hpp"

namespace mpm {

/// Reads and validates the scene file `file`. Throws SceneError (also when the file cannot be read).
SceneDescription load_scene(const std::filesystem::path& file);

/// Validates the scene given as YAML text; `file_name_for_messages` is used in error locations and
/// stored in SceneDescription::file. Throws SceneError.
SceneDescription parse_scene(const std::string& yaml_text, const std::string& file_name_for_messages);

}  // namespace mpm
