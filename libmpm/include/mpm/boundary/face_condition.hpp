#pragma once
/// \file boundary/face_condition.hpp
/// What a condition on one face of the grid box does at each stage of a step (engine layer: no scene language).
/// GridBoundary (grid_boundary.hpp) holds one per face that has one and calls them, in face order, from the
/// module phases of the step: tractions after P2G, velocity constraints at every grid-velocity stage, particle
/// removal at the end of the step. The kinds a scene can name, with their keys and traits, are registered in
/// face_condition_kind.hpp; each kind makes its condition.

#include <functional>
#include <optional>

#include "mpm/core/exact_sum.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/grid/node_runs.hpp"

namespace mpm {

/// Particles beyond this plane leave the run at the end of the step (an outflow face): those with
/// x[axis] > threshold on an upper face, x[axis] < threshold on a lower one.
struct RemovalPlane {
  int axis = 0;
  bool upper = true;
  Real threshold = 0;  ///< m
  bool beyond(Real coordinate) const { return upper ? coordinate > threshold : coordinate < threshold; }
};

template <int Dim>
class FaceCondition {
 public:
  explicit FaceCondition(int face) : face_(face) {}
  virtual ~FaceCondition() = default;
  FaceCondition(const FaceCondition&) = delete;
  FaceCondition& operator=(const FaceCondition&) = delete;

  /// The face (0 .. 2 Dim - 1, the order of face_names).
  int face() const { return face_; }
  /// Whether the condition holds component c of the nodal velocity of its nodes.
  virtual bool holds(int /*component*/) const { return false; }
  /// Whether it holds the normal velocity at 0 for all time (fixed, slip): a wall. The position updates clamp
  /// particles to a wall (GridBoundary::wall_lower/upper).
  virtual bool is_wall() const { return false; }
  /// Sets the held components of `member` of the face's nodes in `nodes` to their value at time t.
  virtual void constrain(NodeArray<NodeVelocity<Dim>>& /*velocity*/, VecU<Dim> NodeVelocity<Dim>::* /*member*/,
                         Real /*t*/, NodeRuns /*nodes*/) const {}
  virtual bool has_traction() const { return false; }
  /// Adds the face's traction at time t to the nodal forces of its nodes in `nodes` that have mass.
  virtual void add_traction(NodeArray<NodeRecord<Dim>>& /*node*/, Real /*t*/, NodeRuns /*nodes*/) const {}
  /// For every node of the face in `nodes` and every traction component, f(node, component, F) with F = t_c(t) A_I the
  /// force add_traction() adds there (N; per radian in axisymmetric coordinates): for a module that shares it among
  /// fields of its own (multi-velocity contact, GridBoundary::traction_forces).
  virtual void traction_forces(Real /*t*/, NodeRuns /*nodes*/,
                               const std::function<void(Index, int, Real)>& /*f*/) const {}
  /// Whether the condition can do work on the bodies (a moving velocity condition, a traction).
  virtual bool does_work() const { return false; }
  /// For every node of `nodes` with mass above `mass_cutoff` and every held component, f(node, component, R) with R
  /// the force the condition exerts on the node in the step from t to t + dt (GridBoundary::reactions).
  virtual void reactions(const NodeArray<NodeRecord<Dim>>& /*node*/, const Vec<Dim>& /*gravity*/, Real /*mass_cutoff*/,
                         Real /*t*/, Real /*dt*/, const std::function<void(Index, int, Real)>& /*f*/,
                         NodeRuns /*nodes*/) const {}
  /// For every node of `nodes` with mass above `mass_cutoff` and every held component, f(node, component, J) with J
  /// = m_I v_c(t) − p_Ic, the momentum the condition sets on the mapped velocity at time t (theory eq. 13.2;
  /// GridBoundary::mapped_impulses).
  virtual void mapped_impulses(const NodeArray<NodeRecord<Dim>>& /*node*/, Real /*mass_cutoff*/, Real /*t*/,
                               const std::function<void(Index, int, Real)>& /*f*/, NodeRuns /*nodes*/) const {}
  /// Adds the work (J) the condition does in the step from t to t + dt to `w`, over the nodes of `owned` (and
  /// `nodes`) only (GridBoundary::work).
  virtual void add_work(ExactSum& /*w*/, const NodeArray<NodeRecord<Dim>>& /*node*/,
                        const NodeArray<NodeVelocity<Dim>>& /*velocity*/, const Vec<Dim>& /*gravity*/,
                        Real /*mass_cutoff*/, Real /*t*/, Real /*dt*/, NodeMask /*owned*/, NodeRuns /*nodes*/) const {}
  /// The plane beyond which particles leave the run through this face, or none (they stay, and one that leaves
  /// the grid stops the run: the stability guard).
  virtual std::optional<RemovalPlane> removal() const { return std::nullopt; }

 private:
  int face_;
};

}  // namespace mpm
