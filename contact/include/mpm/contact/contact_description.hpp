#pragma once
/// \file contact_description.hpp
/// The scene's `contact:` section as read by the loader (docs/scene-reference.md, "contact"): plain data,
/// names not yet resolved to body indices.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace mpm::contact {

/// Friction coefficient and thermal contact conductance of one pair of bodies (each overrides the section's
/// default when given).
struct PairFriction {
  std::array<std::string, 2> bodies;
  std::optional<double> friction;
  std::optional<double> thermal_conductance;  ///< W/(m^2 K)
  SourceLocation where;
};

/// A body of rigid particles (material model `rigid`) moving with a prescribed velocity.
struct RigidBodyDescription {
  std::string body;
  std::array<std::string, 3> velocity{"0", "0", "0"};  ///< m/s, muparser expressions of t
  SourceLocation where;
};

/// A rigid plane (wall): the half-space (x - point).normal <= 0 is solid; it may move.
struct PlaneDescription {
  std::string name;
  std::array<double, 3> point{0, 0, 0};   ///< m, a point of the plane at t = 0
  std::array<double, 3> normal{0, 1, 0};  ///< outward normal of the wall (towards the bodies), normalised
  double friction = 0;
  std::array<std::string, 3> velocity{"0", "0", "0"};  ///< m/s, expressions of t
  SourceLocation where;
};

/// Face conditions of one body's own velocity field (`contact.body_boundaries`): on the faces given they replace
/// grid.boundary's conditions for this body only (a base clamped where the other bodies slip).
struct BodyBoundaryDescription {
  std::string body;
  /// In the order of GridDescription::face_names; none: the face keeps grid.boundary's condition.
  std::array<std::optional<FaceDescription>, 6> faces{};
  SourceLocation where;
};

struct ContactDescription {
  double friction = 0;  ///< default Coulomb coefficient of every pair of bodies
  /// Default thermal contact conductance h of every pair of bodies, W/(m^2 K) (docs/theory.md eq. TC.1); none:
  /// perfect contact (the bodies share the temperature at their common nodes).
  std::optional<double> thermal_conductance;
  SourceLocation thermal_conductance_where;  ///< of the section's `thermal_conductance` value
  std::vector<PairFriction> pairs;
  std::string normals = "mass_gradient";  ///< "mass_gradient" (eq. 5.12) or "density" (eqs 5.9-5.11)
  std::string onset = "particle_gap";     ///< "particle_gap" (the default) or "grid" (contact nodes, the paper)
  std::vector<RigidBodyDescription> rigid_bodies;
  std::vector<PlaneDescription> planes;
  std::vector<BodyBoundaryDescription> body_boundaries;
  std::string force_file;     ///< CSV of contact forces, relative to output.directory; empty: none
  double force_interval = 0;  ///< s between CSV rows (0: every step); forces are averaged over it
  SourceLocation where;
};

}  // namespace mpm::contact
