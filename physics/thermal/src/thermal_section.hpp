#pragma once
// The parser of the `thermal:` scene section (registered by register.cpp).
#include <yaml-cpp/yaml.h>

#include <any>

#include "mpm/scene.hpp"

namespace mpm::thermal {

/// Reads and checks `node` (the value of `thermal:`); returns a ThermalDescription. Throws SceneError.
std::any parse_thermal_section(const YAML::Node& node, const SceneDescription& scene);

}  // namespace mpm::thermal
