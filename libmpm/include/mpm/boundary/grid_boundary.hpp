#pragma once
/// \file boundary/grid_boundary.hpp
/// The conditions on the faces of the grid box, as one module of the step (module.hpp): the faces' tractions are
/// added to the nodal forces after P2G (phase_after_p2g), their velocity constraints set the nodal velocities at
/// every grid-velocity stage (phase_grid_velocity: v^t, v~^{t+dt}, MUSL's and TLMPM's re-mapped v^{t+dt}), and
/// the particles that crossed an outflow face are removed at the end of the step (phase_end_of_step) and booked
/// (boundary/outflow_books.hpp). The simulation adds it before every other module, so it runs first in each
/// phase: the conditions hold before contact, the energy sentinel or a reaction history read the grid.
/// The scene's kinds (fixed, slip, prescribed, outflow, ...) are in face_condition_kind.hpp; each makes a
/// FaceCondition (face_condition.hpp).

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "mpm/boundary/face_condition.hpp"
#include "mpm/boundary/outflow_books.hpp"
#include "mpm/simulation/module.hpp"

namespace mpm {

template <int Dim>
class GridBoundary final : public Module<Dim> {
 public:
  /// No condition on any face.
  GridBoundary() = default;
  /// At most one condition per face, in any order (they are kept, and run, in face order).
  GridBoundary(const GridGeometry<Dim>& g, std::vector<std::unique_ptr<FaceCondition<Dim>>> conditions);
  ~GridBoundary() override;
  GridBoundary(GridBoundary&&) noexcept;
  GridBoundary& operator=(GridBoundary&&) noexcept;

  std::string_view name() const override { return "grid_boundary"; }
  /// The phases its conditions need: none for a box without conditions (it then need not join the step).
  unsigned phases() const override;
  /// Velocity and traction conditions act on nodes (every rank sets its own); removal is decided per particle from
  /// its position, and the books are reduced over the ranks (exact sums).
  std::string why_not_distributed() const override { return {}; }
  /// The tractions at t (apply_traction).
  void after_p2g(StepContext<Dim>& ctx) override;
  /// The velocity constraints of the stage: `mapped` at t, `updated` at t + dt, `remapped` (in `mapped`) at t + dt.
  void on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) override;
  /// Removes the particles beyond an outflow face and books them (the first face in face order that a particle
  /// crossed takes it). A distributed run reduces the step's books over the ranks (one `any`, and a sum when a
  /// particle left), so every rank holds the same books.
  void end_of_step(StepContext<Dim>& ctx) override;
  /// The outflow books and notices (nothing without an outflow face).
  void save_state(StateArchive& archive, const std::string& prefix) const override;
  void restore_state(const StateArchive& archive, const std::string& prefix) override;

  /// No condition on any face.
  bool empty() const { return conditions_.empty(); }
  bool has_traction() const;
  /// Adds every face's traction at time t to the nodal forces (nodes with mass only; only the nodes of `nodes`,
  /// the step's StepContext::active_nodes: outside them no particle reaches a node).
  void apply_traction(NodeArray<NodeRecord<Dim>>& node, Real t, NodeRuns nodes = {}) const;
  /// The forces apply_traction() adds, one call f(node, component, F) per face node of `nodes` and traction component
  /// (FaceCondition::traction_forces), whatever the nodal masses: multi-velocity contact shares them among the bodies'
  /// own fields.
  void traction_forces(Real t, NodeRuns nodes, const std::function<void(Index, int, Real)>& f) const;
  /// Sets the held components of `member` of every face node of `nodes` to their value at time t, face after face
  /// (the contact module applies them to each body's own field with this; the implicit scheme probes the held
  /// components with it).
  void apply(NodeArray<NodeVelocity<Dim>>& velocity, VecU<Dim> NodeVelocity<Dim>::*member, Real t,
             NodeRuns nodes = {}) const;
  /// Bounds that keep particles inside the walls: on an axis whose face holds the normal velocity at 0
  /// (`fixed` or `slip`), the face's coordinate; elsewhere -inf / +inf. The position updates clamp to
  /// them, so that a particle carried past a wall by the velocity of a nearly empty node (a round-off or
  /// small-mass effect, not physics) is put back onto the wall instead of stopping the run.
  const Vec<Dim>& wall_lower() const { return wall_lower_; }
  const Vec<Dim>& wall_upper() const { return wall_upper_; }
  /// The box the stability guard keeps particles in: the grid's, open (-inf / +inf) on the outflow faces, whose
  /// particles leave at the end of the step instead of stopping the run.
  Vec<Dim> keep_lower(const GridGeometry<Dim>& g) const;
  Vec<Dim> keep_upper(const GridGeometry<Dim>& g) const;
  /// True when `face` (0 .. 2 Dim - 1, the order of face_names) holds a velocity component.
  bool constrains_face(int face) const;
  /// The force the velocity conditions of `face` exert on the grid in the step from t to t + dt: for every
  /// node with mass above `mass_cutoff` and every component the face holds, calls f(node, component, R) with
  /// R = m_I (v(t + dt) - v(t)) / dt - (f_I + m_I g)_c, what the condition adds to the nodal force (with
  /// gravity) for the node to follow the prescribed velocity v (0 for a fixed or slip face). `node` holds the
  /// nodal masses and forces of the step (after P2G and tractions). A node held in the same component by two
  /// faces (a shared edge) is reported for both. Used by reaction histories only.
  void reactions(int face, const NodeArray<NodeRecord<Dim>>& node, const Vec<Dim>& gravity, Real mass_cutoff, Real t,
                 Real dt, const std::function<void(Index, int, Real)>& f, NodeRuns nodes = {}) const;
  /// The momentum the velocity conditions of `face` set on the mapped velocities at time t: for every node with
  /// mass above `mass_cutoff` and every component the face holds, f(node, component, m_I v(t) − p_Ic) (theory eq.
  /// 13.2: the particles take (1 − α) of it with the FLIP fraction α, all of it with PIC, APIC and PolyPIC). Used
  /// by reaction histories only.
  void mapped_impulses(int face, const NodeArray<NodeRecord<Dim>>& node, Real mass_cutoff, Real t,
                       const std::function<void(Index, int, Real)>& f, NodeRuns nodes = {}) const;
  /// True when a face condition can do work on the bodies: a prescribed velocity other than 0, or a traction.
  bool does_work() const;
  /// The work (J) the face conditions do on the grid in the step from t to t + dt, for the energy sentinel
  /// (energy_sentinel.hpp; FaceCondition::add_work). `node` as for reactions(); every node term is summed exactly,
  /// over the nodes of `owned` only (a distributed run's rank, StepContext::owned_nodes; the ranks' sums are then
  /// merged).
  ExactSum work(const NodeArray<NodeRecord<Dim>>& node, const NodeArray<NodeVelocity<Dim>>& velocity,
                const Vec<Dim>& gravity, Real mass_cutoff, Real t, Real dt, NodeMask owned = {},
                NodeRuns nodes = {}) const;

  /// Whether a face lets particles out (outflow).
  bool removes_particles() const { return !removals_.empty(); }
  /// The books of every outflow face since t = 0, in face order (the same on every rank).
  const std::vector<OutflowBook>& outflow() const { return books_; }
  /// J: the energy that left, sum over the outflow faces of kinetic + strain + gravity potential + plastic work
  /// (EnergyBalance::total() of the removed particles): the energy sentinel's E_out (docs/theory.md §8).
  Real outflow_energy() const;
  /// The first departure of each body through each face, in the order they happened: the run loop logs the
  /// message() of those whose step is the step just taken.
  const std::vector<OutflowNotice>& outflow_notices() const { return notices_; }
  /// One line per outflow face for the run's final summary ("outflow y_max: 120 particles, 0.3 kg, ...").
  std::vector<std::string> outflow_summary() const;

 private:
  std::vector<std::unique_ptr<FaceCondition<Dim>>> conditions_;  ///< in face order
  Vec<Dim> wall_lower_ = Vec<Dim>::Constant(-std::numeric_limits<Real>::infinity());
  Vec<Dim> wall_upper_ = Vec<Dim>::Constant(std::numeric_limits<Real>::infinity());
  std::vector<RemovalPlane> removals_;  ///< the outflow faces' planes, in face order (books_ alike)
  std::vector<OutflowBook> books_;
  std::vector<OutflowNotice> notices_;
  ParticleRemover<Dim> remover_;  ///< takes the leaving particles out and books them
};

}  // namespace mpm
