#pragma once
// The parser of the `thermal:` scene section (registered by register.cpp).
#include <any>
#include <vector>

#include "mpm/scene/key_spec.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::thermal {

/// The section's keys (docs/scene-reference.md, thermal), which parse_thermal_section reads through.
const std::vector<io::KeySpec>& thermal_keys();

/// Reads and checks `section` (the value of `thermal:`) through the scene's reader; returns a
/// ThermalDescription. Throws SceneError.
std::any parse_thermal_section(const io::YamlReader& reader, const io::YamlValue& section,
                               const SceneDescription& scene);

}  // namespace mpm::thermal
