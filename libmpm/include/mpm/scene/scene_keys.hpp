#pragma once
/// \file scene_keys.hpp
/// The key specs (io/key_spec.hpp) of the scene's sections: what each section's reader accepts, with unit,
/// range, default and description. The readers in src/scene/ read through them, `mpm reference` prints them,
/// the tables of docs/scene-reference.md are generated from them (scene_reference.hpp) and `mpm run --restart`
/// takes the keys a fork may change from them. A module's section declares its keys in its SceneExtension.

#include <vector>

#include "mpm/scene/key_spec.hpp"

namespace mpm {

/// `grid:` (src/scene/grid_section.cpp); its `boundary:` holds per face a condition of a registered kind.
const std::vector<io::KeySpec>& grid_keys();
/// `output:` (src/scene/output_section.cpp), with `checkpoint:` and the common keys of `histories:` entries.
const std::vector<io::KeySpec>& output_keys();
/// `solver:` (src/scene/solver_section.cpp): the core's keys, then those a registered scheme owns
/// (register_scheme_solver_keys, scene_extension.hpp), each refused with any other scheme. Built on each call: the
/// schemes and the shape functions it lists are the registered ones.
std::vector<io::KeySpec> solver_keys();
/// One entry of `output.histories` (src/scene/histories_section.cpp): the keys every history kind takes.
const std::vector<io::KeySpec>& history_keys();
/// One entry of `bodies:` (src/scene/bodies_section.cpp).
const std::vector<io::KeySpec>& body_keys();
/// One entry of `sets:` (src/scene/sets_section.cpp).
const std::vector<io::KeySpec>& set_keys();
/// One entry of `conditions:` (src/scene/sets_section.cpp).
const std::vector<io::KeySpec>& condition_keys();
/// One entry of `materials:` besides its model's parameters (src/scene/materials_section.cpp).
const std::vector<io::KeySpec>& material_keys();
/// What a fork may do with a material's parameters and model keys (src/scene/materials_section.cpp): change
/// every registered model's parameters ("materials.*.youngs_modulus") but the density, from which the particles'
/// masses were computed at t = 0 (they come from the checkpoint); a model's own keys (MaterialModel::keys) by
/// their specs.
std::vector<io::ForkRule> material_fork_rules();
/// `failure:` of a material (src/scene/failure_block.cpp): the criteria and the action of failure_criteria.hpp.
const std::vector<io::KeySpec>& failure_keys();

/// The top level of a scene (src/scene_loader.cpp): the core's sections, then the registered modules' (sorted),
/// each with the keys it declares (none for a section whose reader does not read through specs yet).
std::vector<io::KeySpec> scene_keys();

}  // namespace mpm
