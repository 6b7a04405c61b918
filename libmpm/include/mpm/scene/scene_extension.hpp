#pragma once
/// \file scene_extension.hpp
/// How an optional module joins a scene: the one registry through which contact/ (`contact:`) and
/// physics/thermal (`thermal:`) plug into the loader and the builder, which know no module. A module
/// registers its top-level section's key, a parser that turns the YAML node into its own plain
/// description (stored in SceneDescription::extensions), and builders for one or both of two stages:
///   prepare: before the Simulation exists, i.e. before its first snapshot, on the filled bodies, so that
///            the module can add particle fields (thermal: temperature, heat flux). Called for every
///            registered extension, section or not (it may check that nothing asks for it without the
///            section); returns the Module to add, or nullptr when the scene does not use it.
///   build:   on the built Simulation, when the module needs its bodies in place (contact: per-body
///            grids). Called only when the scene has the section.
/// A scene that uses no module constructs nothing and runs nothing of it.

#include <any>
#include <memory>
#include <string>
#include <vector>

#include "mpm/scene/key_spec.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/simulation/module.hpp"

namespace mpm {

namespace io {
class YamlReader;
struct YamlValue;
}  // namespace io

template <int Dim>
class Simulation;

/// Reads the section through `reader` (io/yaml_reader.hpp; `section` is the value of the top-level key, its
/// path that key), after the scene's other sections; throws SceneError naming file, line and key. The returned
/// value is stored in SceneDescription::extensions[key].
using SectionParser = std::any (*)(const io::YamlReader& reader, const io::YamlValue& section,
                                   const SceneDescription& scene);
/// Sets the defaults the section implies for keys of other sections that the scene does not give (contact: the
/// velocity transfer); called after every section is read, only when the scene has the section.
using SectionCompleter = void (*)(SceneDescription& scene);
/// Adds the module to a simulation built from `scene`; throws SceneError for what needs the built bodies.
template <int Dim>
using SectionBuilder = void (*)(const SceneDescription& scene, Simulation<Dim>& simulation);
/// The module for these bodies before the simulation is built, or nullptr; throws SceneError.
template <int Dim>
using SectionPreparer = std::shared_ptr<Module<Dim>> (*)(const SceneDescription& scene, std::vector<Body<Dim>>& bodies,
                                                         const GridGeometry<Dim>& grid);

struct SceneExtension {
  std::string key;  ///< top-level YAML key
  /// Null: the module has no section (no top-level key; its preparer reads the materials' keys, e.g. the fluids'
  /// pressure_smoothing); only prepare_* are then called.
  SectionParser parse = nullptr;
  SectionCompleter complete = nullptr;
  SectionPreparer<1> prepare_1d = nullptr;
  SectionPreparer<2> prepare_2d = nullptr;
  SectionPreparer<3> prepare_3d = nullptr;
  SectionBuilder<1> build_1d = nullptr;
  SectionBuilder<2> build_2d = nullptr;
  SectionBuilder<3> build_3d = nullptr;
  /// The section's keys (io/key_spec.hpp), which its parser reads through (io/spec_map.hpp): the scene reference's
  /// table of the section, `mpm reference --section KEY`, and the keys a fork may change when it continues a
  /// checkpoint (`mpm run --restart` with a changed scene: KeySpec::run_control) come from them.
  std::vector<io::KeySpec> keys{};
  /// One line for the scene reference's table of sections.
  std::string description{};
};

/// Registers (or replaces) the section with this key. Called by a module's register_module().
void register_scene_extension(SceneExtension extension);
/// The registered section with this key, or nullptr.
const SceneExtension* find_scene_extension(const std::string& key);
/// Keys of the registered sections, sorted.
std::vector<std::string> scene_extension_keys();

/// Calls every registered preparer (in key order) on the filled bodies; returns the modules to add.
template <int Dim>
std::vector<std::shared_ptr<Module<Dim>>> prepare_scene_extensions(const SceneDescription& scene,
                                                                   std::vector<Body<Dim>>& bodies,
                                                                   const GridGeometry<Dim>& grid);
/// Calls the builders of the scene's extension sections on a freshly built simulation.
template <int Dim>
void build_scene_extensions(const SceneDescription& scene, Simulation<Dim>& simulation);

/// Declares the keys of `solver:` that only the registered scheme `scheme` reads (a module's scheme: `implicit` its
/// `solver.implicit` map), with their specs: the solver's reader allows them and refuses them with any other scheme,
/// and the reference lists them in the table of `solver` (solver_keys(), scene_keys.hpp). The scheme's
/// SchemeSpec::parse reads them. Called by a module's register_module().
void register_scheme_solver_keys(const std::string& scheme, std::vector<io::KeySpec> keys);
/// A key of `solver:` that one scheme owns.
struct SchemeSolverKey {
  io::KeySpec spec;
  std::string scheme;
};
/// Every key registered by register_scheme_solver_keys, ordered by scheme name, then as declared.
std::vector<SchemeSolverKey> scheme_solver_keys();

}  // namespace mpm
