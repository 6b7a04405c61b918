#pragma once
/// \file boundary/velocity_face.hpp
/// The velocity and traction conditions of a face (review §4.2.1-4.2.2), what the kinds `fixed`, `slip` and
/// `prescribed` (`{velocity: [...], traction: [...]}`) make: per component a velocity held at its value (an
/// expression of t; "0": at rest) at every stage where the algorithms overwrite the nodal velocities
/// (v^t, v~^{t+dt}, v^{t+dt}), and per component a traction added to the nodal forces.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mpm/boundary/face_condition.hpp"

namespace mpm {

class Expression;

/// What a velocity or traction face holds, per component (x, y, z): a muparser expression of `t` (seconds), or
/// nothing. A velocity of "0" holds the component at rest (on the normal axis: a wall).
struct VelocityFaceSpec {
  std::array<std::optional<std::string>, 3> velocity;  ///< m/s; empty: the component is free
  std::array<std::optional<std::string>, 3> traction;  ///< Pa; empty: none
};

template <int Dim>
class VelocityFace final : public FaceCondition<Dim> {
 public:
  VelocityFace(const GridGeometry<Dim>& g, int face, const VelocityFaceSpec& spec);
  ~VelocityFace() override;

  bool holds(int component) const override;
  bool is_wall() const override { return wall_; }
  /// Every held component of `member` of the face nodes of `nodes` (the step's StepContext::active_nodes; no
  /// particle reads a node outside them) set to its value at t, evaluated once per face.
  void constrain(NodeArray<NodeVelocity<Dim>>& velocity, VecU<Dim> NodeVelocity<Dim>::*member, Real t,
                 NodeRuns nodes) const override;
  bool has_traction() const override { return !traction_.empty(); }
  /// f_I += t(t) A_I, with A_I the face area of node I (a cell face shared by its corner nodes; per unit
  /// out-of-plane size in 1D/2D; in axisymmetric coordinates the revolved face, axisym::face_node_area). Nodes
  /// without mass get nothing (they are not part of the body).
  void add_traction(NodeArray<NodeRecord<Dim>>& node, Real t, NodeRuns nodes) const override;
  void traction_forces(Real t, NodeRuns nodes, const std::function<void(Index, int, Real)>& f) const override;
  /// A prescribed velocity other than 0, or a traction.
  bool does_work() const override;
  /// R = m_I (v(t + dt) - v(t)) / dt - (f_I + m_I g)_c: what the condition adds to the nodal force (with gravity)
  /// for the node to follow the prescribed velocity v (0 for a fixed or slip face).
  void reactions(const NodeArray<NodeRecord<Dim>>& node, const Vec<Dim>& gravity, Real mass_cutoff, Real t, Real dt,
                 const std::function<void(Index, int, Real)>& f, NodeRuns nodes) const override;
  /// J = m_I v(t) − p_Ic: the momentum the condition sets on the mapped velocity.
  void mapped_impulses(const NodeArray<NodeRecord<Dim>>& node, Real mass_cutoff, Real t,
                       const std::function<void(Index, int, Real)>& f, NodeRuns nodes) const override;
  /// A velocity condition: R v dt, R as in reactions() and v the prescribed velocity at t + dt/2; a traction:
  /// f_I . v dt with f_I = t(t) A_I and v the mean of the node's velocity at t and at t + dt (`mapped`, `updated`:
  /// the nodal kinetic energy changes by exactly that work). Every node term summed exactly.
  void add_work(ExactSum& w, const NodeArray<NodeRecord<Dim>>& node, const NodeArray<NodeVelocity<Dim>>& velocity,
                const Vec<Dim>& gravity, Real mass_cutoff, Real t, Real dt, NodeMask owned,
                NodeRuns nodes) const override;

 private:
  struct Held {
    int component = 0;
    std::shared_ptr<const Expression> value;  ///< of t; null means 0
  };
  struct Traction {
    int component = 0;
    std::shared_ptr<const Expression> value;  ///< Pa, of t
  };
  std::vector<Held> held_;
  std::vector<Traction> traction_;
  std::vector<Index> nodes_;
  std::vector<Real> area_;  ///< m^2 per node of nodes_ (with a traction only)
  bool wall_ = false;
};

}  // namespace mpm
