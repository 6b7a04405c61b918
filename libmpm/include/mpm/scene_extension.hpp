#pragma once
/// \file scene_extension.hpp
/// Top-level scene sections owned by optional modules (e.g. `contact:` of contact/). A module registers
/// the section's key, a parser that turns the YAML node into its own plain description (stored in
/// SceneDescription::extensions), and builders that add its Module to a built Simulation. The loader
/// knows no module; a scene without the section never calls them.

#include <any>
#include <memory>
#include <string>
#include <vector>

#include "mpm/scene.hpp"

namespace YAML {
class Node;
}

namespace mpm {

template <int Dim>
class Simulation;

/// Reads the section (the scene's other sections are already read); throws SceneError naming file,
/// line and key. The returned value is stored in SceneDescription::extensions[key].
using SectionParser = std::any (*)(const YAML::Node& section, const SceneDescription& scene);
/// Adds the module to a simulation built from `scene`; throws SceneError for what needs the built bodies.
template <int Dim>
using SectionBuilder = void (*)(const SceneDescription& scene, Simulation<Dim>& simulation);

struct SceneExtension {
  std::string key;  ///< top-level YAML key
  SectionParser parse = nullptr;
  SectionBuilder<1> build_1d = nullptr;
  SectionBuilder<2> build_2d = nullptr;
  SectionBuilder<3> build_3d = nullptr;
};

/// Registers (or replaces) the section with this key. Called by a module's register_module().
void register_scene_extension(SceneExtension extension);
/// The registered section with this key, or nullptr.
const SceneExtension* find_scene_extension(const std::string& key);
/// Keys of the registered sections, sorted.
std::vector<std::string> scene_extension_keys();

/// Calls the builders of the scene's extension sections on a freshly built simulation.
template <int Dim>
void build_scene_extensions(const SceneDescription& scene, Simulation<Dim>& simulation);

}  // namespace mpm
