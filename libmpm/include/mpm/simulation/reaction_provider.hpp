#pragma once
/// \file reaction_provider.hpp
/// What a module that holds the bodies against something rigid (contact/: rigid planes and rigid bodies)
/// tells a reaction history (`output.histories[].type: reaction`), without the core naming the module: the
/// names of its rigid partners and the force each exerted on the deformable bodies in the last step, and the
/// contact force on each body from each partner.

#include <optional>
#include <string>
#include <vector>

#include "mpm/core/types.hpp"

namespace mpm {

/// The force a rigid partner exerted on the deformable bodies during one step.
template <int Dim>
struct Reaction {
  Vec<Dim> force = Vec<Dim>::Zero();  ///< N (per unit out-of-plane size in 2D and 1D)
  /// sum over the nodes of x_I x f_I about the origin (the moment about p is first_moment - p x force), N m
  Vec3 first_moment = Vec3::Zero();
};

/// Implemented by a Module besides Module<Dim>; found by dynamic_cast when a reaction history is built.
template <int Dim>
class ReactionProvider {
 public:
  virtual ~ReactionProvider() = default;
  /// The names a reaction history can ask for (`plane:` or `body:`), in a fixed order.
  virtual std::vector<std::string> reaction_partners() const = 0;
  /// The force partner `k` (an index into reaction_partners()) exerted in the last step.
  virtual Reaction<Dim> last_reaction(int k) const = 0;
  /// The velocity of partner `k` at time `t` (m/s), for the work it does on the bodies (the energy sentinel,
  /// energy_sentinel.hpp: a plane's at the middle of each step, a rigid body's at its end). The default, at rest,
  /// is right for a partner that does not move.
  virtual Vec<Dim> partner_velocity(int /*k*/, Real /*t*/) const { return Vec<Dim>::Zero(); }
  /// J: the work partner `k` did on the bodies in the last step, when the module computes it itself (a held particle
  /// set whose velocity varies over its nodes); nothing: the energy sentinel takes force . partner_velocity dt.
  virtual std::optional<Real> last_work(int /*k*/) const { return std::nullopt; }
  /// The names of what can push on a body (`from:` of a reaction history `on:` a body), in a fixed order: the
  /// bodies (index = the scene's body index), then the rigid planes.
  virtual std::vector<std::string> contact_partners() const { return {}; }
  /// The force the contact exerted in the last step on body `body` (the scene's index) from partner `partner` (an
  /// index into contact_partners()), or from all of them (-1).
  virtual Reaction<Dim> last_contact_force(int /*body*/, int /*partner*/) const { return {}; }
};

}  // namespace mpm
