#pragma once
/// \file sets/set_conditions.hpp
/// What `conditions:` prescribes on particle sets (docs/scene-reference.md#conditions, docs/theory.md §17), as one
/// module of the step:
/// - held velocity components: every grid node a particle of the set reaches (a non-zero weight at its position of
///   the start of the step; TLMPM: its reference position) takes the prescribed velocity v(x_I, t) at the mapped
///   stage, v(x_I, t + dt) at the updated and re-mapped stages, like a grid face's nodes (eq. 13.1). The force this
///   exerts on the bodies is the set's reaction (reaction_provider.hpp: a `reaction` history with `set:`), eq. 17.1;
/// - a total force F(t) on a set, shared by its particles in proportion to their mass: the body force per unit mass
///   b_p = F / M_set (keys::body_force), which the transfers add to gravity and the energy audit books as external
///   work.
/// Nodes are marked on every rank from the particles it holds and joined over the ranks, and every sum is exact and
/// reduced, so a run gives the same bits for any rank count.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mpm/core/expression.hpp"
#include "mpm/simulation/module.hpp"
#include "mpm/simulation/reaction_provider.hpp"

namespace mpm {

/// A set whose velocity components are held.
struct HeldSet {
  std::string name;                                     ///< the set's (the reaction partner's name)
  std::uint32_t mask = 0;                               ///< its bit (particle_sets.hpp)
  std::vector<int> bodies;                              ///< the bodies it may have particles in
  std::array<std::shared_ptr<Expression>, 3> velocity;  ///< of x, y, z, t per component; null: free
};

/// A set loaded by a total force.
struct LoadedSet {
  std::uint32_t mask = 0;
  std::vector<int> bodies;
  std::array<std::shared_ptr<Expression>, 3> force;  ///< of t per component (N); null: none
};

/// The module, or nullptr when there is nothing to apply. `shape_function` names the scene's shape function (the
/// nodes a particle reaches), `total_lagrangian` the scheme's trait (stencils at the reference positions) and
/// `pic_share` the share 1 − α of the mapped stage's impulse the particles take (theory eq. 13.2a).
template <int Dim>
std::shared_ptr<Module<Dim>> make_set_conditions(std::vector<HeldSet> held, std::vector<LoadedSet> loaded,
                                                 const std::string& shape_function, bool total_lagrangian,
                                                 Real pic_share);

}  // namespace mpm
