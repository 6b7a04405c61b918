#pragma once
/// \file sets/particle_sets.hpp
/// Named particle sets (`sets:`, docs/scene-reference.md#sets): which particles belong to which set, decided once
/// at t = 0 from the body, the region of the initial position and the id, and kept in the particle field
/// `particle_sets`, one bit per set (bit k: the scene's k-th set). As a particle field it moves with its particle
/// through sorting, MPI migration, checkpoints and the stability guard's snapshots, and is written like any field.

#include <cstdint>
#include <memory>

#include "mpm/particles/body.hpp"
#include "mpm/particles/field_key.hpp"
#include "mpm/scene/scene.hpp"
#include "mpm/simulation/module.hpp"

namespace mpm {

/// Sets a scene may declare: the bits of the field.
inline constexpr int max_particle_sets = 32;

namespace keys {
/// Bit k set: the particle belongs to the scene's k-th set. Added to every body when the scene has sets.
inline constexpr FieldKey<std::uint32_t> particle_sets{"particle_sets"};
}  // namespace keys

/// The bit of set `index` (an index into SceneDescription::sets).
inline std::uint32_t set_bit(int index) { return std::uint32_t{1} << index; }

/// Whether particle i of `p` belongs to a set of `mask` (false when the body carries no set field).
template <int Dim>
bool in_sets(const ParticleSet<Dim>& p, Index i, std::uint32_t mask) {
  return p.has_field(keys::particle_sets) && (p.field(keys::particle_sets)[static_cast<std::size_t>(i)] & mask) != 0;
}

/// Marks the particles of `body`, as filled (positions and ids of t = 0), with the scene's sets, and gives the
/// particles of a set with `initial_velocity` that velocity. Adds the field when the scene has sets. Throws
/// ShapeError when a set's region cannot be made (its file).
template <int Dim>
void mark_particle_sets(const SceneDescription& scene, Body<Dim>& body);

/// The fields the sets and their conditions need on `body`: `particle_sets` when the scene has sets, `body_force`
/// when a set of the body is loaded by a force. For the built bodies and for a restart's prototypes alike.
template <int Dim>
void add_set_fields(const SceneDescription& scene, Body<Dim>& body);

/// The module of the scene's held and loaded sets (set_conditions.hpp), or nullptr when it has none. Throws
/// SceneError at a condition the scheme cannot apply (one that runs no grid-velocity stages: implicit).
template <int Dim>
std::shared_ptr<Module<Dim>> scene_set_conditions(const SceneDescription& scene);

/// The index of the set named `name` in scene.sets, or -1.
int find_set(const SceneDescription& scene, const std::string& name);

}  // namespace mpm
