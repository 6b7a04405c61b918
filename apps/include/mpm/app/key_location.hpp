#pragma once
/// \file key_location.hpp
/// Where a key is in the scene file, for refusals and warnings found after the scene was read (the memory
/// estimate, the step count): the description keeps only some places, so the file's text is read again there.

#include <string>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace mpm::app {

/// The place of the value at `path` (map keys from the top, e.g. {"materials", "steel", "density"}); of the
/// deepest part of the path that exists when the rest does not; the file alone when none does.
SourceLocation locate_key(const SceneDescription& scene, const std::vector<std::string>& path);

/// The place of `key` in the body defined at `body` (its BodyDescription::where); the body's own when absent.
SourceLocation locate_body_key(const SceneDescription& scene, const SourceLocation& body, const std::string& key);

}  // namespace mpm::app
