#pragma once
/// \file boundary_conditions.hpp
/// Velocity constraints on the nodes of the grid box faces (review §4.2.1): per face and per component
/// free, fixed (0) or prescribed as an expression of t. Applied to the nodal velocities at every stage
/// where the algorithms overwrite them (v^t, v~^{t+dt}, v^{t+dt}).

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "mpm/exact_sum.hpp"
#include "mpm/grid.hpp"
#include "mpm/node_runs.hpp"
#include "mpm/scene.hpp"

namespace mpm {

class Expression;

template <int Dim>
class GridBoundary {
 public:
  GridBoundary() = default;
  /// `faces` in the order x_min, x_max, y_min, y_max, z_min, z_max (only 2*Dim are read).
  GridBoundary(const GridGeometry<Dim>& g, const std::array<FaceBoundary, 6>& faces);
  ~GridBoundary();
  GridBoundary(GridBoundary&&) noexcept;
  GridBoundary& operator=(GridBoundary&&) noexcept;

  bool empty() const { return constraints_.empty(); }
  bool has_traction() const { return !tractions_.empty(); }
  /// Adds the prescribed face tractions at time t to the nodal forces: f_I += t(t) A_I, with A_I the
  /// face area of node I (a cell face shared by its corner nodes; per unit out-of-plane size in 1D/2D; in
  /// axisymmetric coordinates the area of the revolved face, axisym::face_node_area).
  /// Nodes without mass get nothing (they are not part of the body). Only the nodes of `nodes` (the step's
  /// StepContext::active_nodes: outside them no particle reaches a node) are visited.
  void apply_traction(NodeArray<NodeRecord<Dim>>& node, Real t, NodeRuns nodes = {}) const;
  /// Bounds that keep particles inside the walls: on an axis whose face holds the normal velocity at 0
  /// (`fixed` or `slip`), the face's coordinate; elsewhere -inf / +inf. The position updates clamp to
  /// them, so that a particle carried past a wall by the velocity of a nearly empty node (a round-off or
  /// small-mass effect, not physics) is put back onto the wall instead of stopping the run.
  const Vec<Dim>& wall_lower() const { return wall_lower_; }
  const Vec<Dim>& wall_upper() const { return wall_upper_; }
  /// Sets the constrained components of `member` of every face node of `nodes` (the step's
  /// StepContext::active_nodes; no particle reads a node outside them) to their value at time t.
  void apply(NodeArray<NodeVelocity<Dim>>& velocity, VecU<Dim> NodeVelocity<Dim>::*member, Real t,
             NodeRuns nodes = {}) const;
  /// True when `face` (0 .. 2 Dim - 1, the order of GridDescription::face_names) holds a velocity component.
  bool constrains_face(int face) const;
  /// The force the velocity conditions of `face` exert on the grid in the step from t to t + dt: for every
  /// node with mass above `mass_cutoff` and every component the face holds, calls f(node, component, R) with
  /// R = m_I (v(t + dt) - v(t)) / dt - (f_I + m_I g)_c, what the condition adds to the nodal force (with
  /// gravity) for the node to follow the prescribed velocity v (0 for a fixed or slip face). `node` holds the
  /// nodal masses and forces of the step (after P2G and tractions). A node held in the same component by two
  /// faces (a shared edge) is reported for both. Used by reaction histories only.
  void reactions(int face, const NodeArray<NodeRecord<Dim>>& node, const Vec<Dim>& gravity, Real mass_cutoff, Real t,
                 Real dt, const std::function<void(Index, int, Real)>& f, NodeRuns nodes = {}) const;
  /// True when a face condition can do work on the bodies: a prescribed velocity other than 0, or a traction.
  bool does_work() const;
  /// The work (J) the face conditions do on the grid in the step from t to t + dt, for the energy sentinel
  /// (energy_sentinel.hpp): a velocity condition R v dt, with R its force of reactions() and v the prescribed
  /// velocity at t + dt/2; a traction f_I . v dt with f_I = t(t) A_I and v the mean of the node's velocity at t
  /// and at t + dt (`velocity[n].mapped` and `.updated`: the nodal kinetic energy changes by exactly that work).
  /// A fixed or slip face does none. `node` as for reactions(); every node term is summed exactly, over the nodes
  /// of `owned` only (a distributed run's rank, StepContext::owned_nodes; the ranks' sums are then merged).
  ExactSum work(const NodeArray<NodeRecord<Dim>>& node, const NodeArray<NodeVelocity<Dim>>& velocity,
                const Vec<Dim>& gravity, Real mass_cutoff, Real t, Real dt, NodeMask owned = {},
                NodeRuns nodes = {}) const;

 private:
  struct Constraint {
    int face = 0;
    int component = 0;
    std::shared_ptr<const Expression> value;  ///< of t; null means 0
    std::vector<Index> nodes;
  };
  std::vector<Constraint> constraints_;
  struct Traction {
    int component = 0;
    std::shared_ptr<const Expression> value;  ///< Pa, of t
    std::vector<Index> nodes;
    std::vector<Real> area;  ///< m^2 per node
  };
  std::vector<Traction> tractions_;
  Vec<Dim> wall_lower_ = Vec<Dim>::Constant(-std::numeric_limits<Real>::infinity());
  Vec<Dim> wall_upper_ = Vec<Dim>::Constant(std::numeric_limits<Real>::infinity());
};

}  // namespace mpm
