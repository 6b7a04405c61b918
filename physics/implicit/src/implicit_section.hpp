#pragma once
// The scene side of the scheme `implicit`: its `solver.implicit:` keys and what it refuses.
#include <any>

#include <vector>

#include "mpm/scene/key_spec.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::implicit {

/// The scheme's own key of `solver:`, the map `implicit` with the options of ImplicitOptions (defaults from here).
const std::vector<io::KeySpec>& implicit_keys();
/// Reads `solver.implicit:` (ImplicitOptions) and refuses, at the offending key, what the scheme does not do.
std::any parse_implicit_solver(const io::YamlReader& reader, const io::YamlMap& solver_map,
                               const SolverDescription& solver, const SceneDescription& scene);
/// After every section is read: refuses the module sections the scheme does not support yet (contact, thermal).
void check_implicit_scene(const io::YamlReader& reader, const io::YamlMap& top, const SceneDescription& scene);

}  // namespace mpm::implicit
