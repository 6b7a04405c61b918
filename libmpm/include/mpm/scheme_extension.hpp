#pragma once
/// \file scheme_extension.hpp
/// How an optional module adds a time-integration scheme (physics/implicit: `implicit`) without the core
/// knowing it: the scheme's name for `solver.scheme`, the keys of `solver:` it owns, a parser for them (and for
/// what the scheme refuses), a check of the whole scene after every section is read, and the makers per
/// dimension. The built-in schemes (SchemeKind) are not here. A scene that names no registered scheme never
/// touches this registry beyond the name lookup of `solver.scheme`.

#include <any>
#include <memory>
#include <string>
#include <vector>

#include "mpm/scene.hpp"
#include "mpm/scheme.hpp"

namespace mpm {

namespace io {
class YamlReader;
class YamlMap;
}  // namespace io

template <int Dim>
using SchemeMaker = std::unique_ptr<Scheme<Dim>> (*)(const SceneDescription& scene);

struct SchemeExtension {
  std::string name;                      ///< the value of `solver.scheme`
  std::vector<std::string> solver_keys;  ///< keys of `solver:` only this scheme reads (e.g. "implicit")
  /// Reads the scheme's keys of `solver:` (`solver` holds what the core read so far: shape function, velocity
  /// transfer) and refuses what the scheme does not support, through the reader (file:line:column: key). Called
  /// before the time step is read. The result is stored in SolverDescription::extension_options.
  std::any (*parse)(const io::YamlReader& reader, const io::YamlMap& solver_map, const SolverDescription& solver,
                    const SceneDescription& scene) = nullptr;
  /// After every section (modules' included) is read: refuses sections the scheme does not support.
  void (*check)(const io::YamlReader& reader, const io::YamlMap& top, const SceneDescription& scene) = nullptr;
  SchemeMaker<1> make_1d = nullptr;
  SchemeMaker<2> make_2d = nullptr;
  SchemeMaker<3> make_3d = nullptr;
  /// True when a fixed dt needs no stability bound (an implicit scheme): the builder then does not refuse a
  /// dt above the CFL bound.
  bool unconditionally_stable = false;
};

/// Registers (or replaces) the scheme with this name. Called by a module's register_module().
void register_scheme_extension(SchemeExtension extension);
/// The registered scheme with this name, or nullptr.
const SchemeExtension* find_scheme_extension(const std::string& name);
/// Names of the registered schemes, sorted.
std::vector<std::string> scheme_extension_names();
/// Every key of `solver:` some registered scheme owns, with its scheme: {key, scheme name}.
std::vector<std::pair<std::string, std::string>> scheme_extension_solver_keys();

/// The scheme of a scene made by the registered extension it names (solver.extension_scheme); throws
/// std::invalid_argument when it is not registered or has no maker in this dimension.
template <int Dim>
std::unique_ptr<Scheme<Dim>> make_extension_scheme(const SceneDescription& scene);

}  // namespace mpm
