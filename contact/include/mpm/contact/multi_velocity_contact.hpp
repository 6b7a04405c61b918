#pragma once
/// \file multi_velocity_contact.hpp
/// Bardenhagen's multi-velocity-field contact (review §5.1, Alg. 6; Bardenhagen et al. 2000), rigid
/// bodies (§4.2.4, Alg. 4) and rigid planes, as a module of the step (module.hpp):
///  - every body gets its own nodal arrays (Body::separate_grid), filled by the schemes' own P2G, so that a
///    scene without contact runs the unchanged single-field path;
///  - after P2G: the contact candidates (nodes with mass of two bodies, or behind a rigid plane), the
///    bodies' normals there (eq. 5.12 or 5.9-5.11) and, with onset `particle_gap`, the particle gap;
///  - at every grid-velocity stage: the bodies' nodal velocities, the boundary conditions, and at the
///    `updated` stage the contact correction (eqs 5.2-5.8); MUSL's re-mapped velocity again against planes and
///    rigid bodies, between two deformable bodies only with `correct_remapped` (the paper's Remark 33, which adds
///    energy there: docs/theory.md §11, "Energy").
/// Contact forces (impulse of the correction / dt) go to a CSV, reaction forces of rigid bodies too.

#include <array>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/core/exact_sum.hpp"
#include "mpm/core/expression.hpp"
#include "mpm/simulation/interface_conductance.hpp"
#include "mpm/simulation/module.hpp"
#include "mpm/simulation/reaction_provider.hpp"

namespace mpm::contact {

enum class NormalMethod { mass_gradient, density };
enum class Onset { grid, particle_gap };

template <int Dim>
struct ContactSettings {
  std::vector<Real> friction;  ///< n x n (n = number of bodies), symmetric
  /// n x n, symmetric: thermal contact conductance h of each pair, W/(m^2 K); +infinity (perfect) when empty
  std::vector<Real> thermal_conductance;
  NormalMethod normals = NormalMethod::mass_gradient;
  Onset onset = Onset::grid;
  struct Rigid {
    int body = 0;
    std::array<std::string, Dim> velocity;  ///< expressions of t, m/s
  };
  std::vector<Rigid> rigid_bodies;
  struct Plane {
    std::string name;
    Vec<Dim> point = Vec<Dim>::Zero();
    Vec<Dim> normal = Vec<Dim>::Unit(Dim - 1);  ///< outward normal of the wall, unit
    Real friction = 0;
    std::array<std::string, Dim> velocity;
  };
  std::vector<Plane> planes;
  /// A body whose own field has its own face conditions (`contact.body_boundaries`): all 2 Dim faces, grid.boundary's
  /// with the body's replacements. Bodies not listed take grid.boundary's (StepContext::boundary).
  struct BodyFaces {
    int body = 0;
    std::shared_ptr<const GridBoundary<Dim>> boundary;  ///< made from the scene's kinds (contact_section.cpp)
  };
  std::vector<BodyFaces> body_faces;
  std::string force_file;  ///< empty: no CSV
  Real force_interval = 0;
  /// MUSL: correct the re-mapped velocity again at nodes of two deformable bodies (the paper's Remark 33; against a
  /// plane or a rigid body it is always corrected). Off: the strain rate of each body is taken from its own
  /// re-mapped velocity there. The second correction changes the velocity the strain rate is taken
  /// from without changing any particle's momentum, and under compression at the node its work
  /// -dt sum f_I . dv_I is positive: it made the colliding cylinders gain energy (docs/theory.md §11, "Energy").
  bool correct_remapped = false;
  /// Correct a node of two deformable bodies only if they also approach in the velocity v^t of the start of the
  /// step; the trial velocity alone is the paper's test (eq. 5.2). With MUSL and USF a correction changes the
  /// particles' kinetic energy by J.v^t to first order: at a node whose bodies separate at v^t (the node criterion
  /// corrects nodes between bodies still apart) that is positive. On by default with onset `grid` and MUSL or USF
  /// (contact_section.cpp; docs/theory.md §11, "Energy").
  bool release_on_start = false;
};

/// The work the contact corrections did in the scheme's energy balance, summed over the run (J, per unit
/// thickness in 2D): how each correction changes the total energy, measured by the corrections themselves.
struct CorrectionWork {
  /// -dt sum f_I . (v_I - v~_I) of the corrections of the re-mapped velocity (MUSL with `correct_remapped`): the
  /// strain energy they add or remove while no particle velocity changes (f_I: the body's internal force).
  Real remapped = 0;
  /// sum J_I . v_I^t of the corrections at the updated stage (J_I: impulse on a body at node I, v_I^t its velocity
  /// at the start of the step; a rigid partner's term with its reaction): positive when bodies that were
  /// separating at the start of the step are corrected, which USF's strain rate (from v^t) does not see.
  Real start_velocity = 0;
};

/// Force on `body` from `other` (a body index, or -1 - plane index), summed over the contact nodes.
template <int Dim>
struct PairForce {
  int body = 0, other = 0;
  Vec<Dim> force = Vec<Dim>::Zero();  ///< N (per unit thickness in 2D)
  Real normal = 0;                    ///< N, compressive part: -sum f.n_body (positive when pressed)
  Real tangential = 0;                ///< N, |sum of the tangential parts|
};

/// The particle passes that need the shape function (normals, gap), dispatched once per body per step.
template <int Dim>
class ShapePasses;

template <int Dim>
class MultiVelocityContact final : public Module<Dim>, public ReactionProvider<Dim>, public InterfaceConductance {
 public:
  /// Gives every body its own nodal arrays; `shape_function` is the scene's (for the normals).
  MultiVelocityContact(const GridGeometry<Dim>& grid, std::vector<Body<Dim>>& bodies, const std::string& shape_function,
                       ContactSettings<Dim> settings);
  ~MultiVelocityContact() override;
  std::string_view name() const override { return "contact"; }
  unsigned phases() const override { return phase_after_p2g | phase_grid_velocity | phase_end_of_step; }
  /// Its scatters (normals, gaps) name their arrays, the corrections are nodal (both sides of a rank boundary hold
  /// the same node values), the forces and works are summed over the nodes a rank owns and reduced, and rank 0
  /// writes the CSV. The density normals (eqs 5.9-5.11) sum a cell array in storage order: not yet.
  void set_writes_files(bool on) override { writes_files_ = on; }
  std::string why_not_distributed() const override {
    return settings_.normals == NormalMethod::density ? "normals: density sums a cell array without ghost exchange"
                                                      : std::string{};
  }
  void after_p2g(StepContext<Dim>& ctx) override;
  void on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) override;
  void end_of_step(StepContext<Dim>& ctx) override;
  /// Plane positions, the impulses since the last CSV row, the onset time, the last forces and the length of
  /// the force CSV (continued by restore_state(), io/continued_file.hpp).
  void save_state(StateArchive& archive, const std::string& prefix) const override;
  void restore_state(const StateArchive& archive, const std::string& prefix) override;

  /// The pair's `thermal_conductance` (W/(m^2 K); +infinity, perfect, when the scene gives none): read by heat
  /// conduction (interface_conductance.hpp), which exchanges q = h (T_b - T_a) across the pair's common nodes.
  Real interface_conductance(int a, int b) const override {
    return settings_.thermal_conductance.empty() ? std::numeric_limits<Real>::infinity()
                                                 : settings_.thermal_conductance[a * body_count_ + b];
  }

  /// Time (end of the step) of the first contact correction, or a negative value if none happened yet.
  Real onset_time() const { return onset_time_; }
  /// Forces of the last step, one entry per pair that touched (bodies, then rigid reactions).
  const std::vector<PairForce<Dim>>& last_forces() const { return last_forces_; }
  /// The work of the corrections since the start of the run (see CorrectionWork).
  const CorrectionWork& correction_work() const { return work_; }
  /// Switches of ContactSettings that tests change on a built simulation (the paper's corrections).
  void set_correct_remapped(bool on) { settings_.correct_remapped = on; }
  void set_release_on_start(bool on) { settings_.release_on_start = on; }
  /// Number of contact nodes (corrected at the `updated` stage) in the last step.
  Index contact_node_count() const { return contact_nodes_last_; }
  /// Position of plane k at the current time (it moves with its velocity).
  Vec<Dim> plane_point(int k) const { return plane_point_[k]; }
  /// The planes' names, then the rigid bodies' (reaction histories, reaction_provider.hpp).
  std::vector<std::string> reaction_partners() const override;
  /// The force partner k exerted on the deformable bodies in the last step (sum of the step's corrections).
  Reaction<Dim> last_reaction(int k) const override;
  /// The bodies, then the planes: the slots of the per-pair forces.
  std::vector<std::string> contact_partners() const override;
  Reaction<Dim> last_contact_force(int body, int partner) const override;
  /// The prescribed velocity at t of partner k: a plane's, then a rigid body's (the energy sentinel's work).
  Vec<Dim> partner_velocity(int k, Real t) const override {
    const int planes = static_cast<int>(settings_.planes.size());
    return k < planes ? plane_velocity(k, t) : rigid_velocity(k - planes, t);
  }

 private:
  /// The face tractions (GridBoundary::traction_forces) on the shared field and, by mass share, on the deformable
  /// bodies' own fields: every body at a loaded node gets the same acceleration from the traction, so the load makes
  /// no relative motion between bodies there, and the momentum and the traction's power (booked on the shared field,
  /// eq. 8.4) are those of the bodies' fields.
  void share_tractions(StepContext<Dim>& ctx);
  void find_candidates(StepContext<Dim>& ctx);
  /// Onset particle_gap with planes: plane_reach_ of every deformable body at the candidate nodes behind each plane.
  void plane_reach(const GridGeometry<Dim>& g, Communicator* comm);
  void body_velocities(StepContext<Dim>& ctx, GridStage stage);
  /// What one correction pass (at one grid-velocity stage) reads: the nodal velocity it corrects, whether the
  /// forces of the step are recorded (the `updated` stage), and the planes' velocities at t + dt.
  struct CorrectionPass {
    VecU<Dim> NodeVelocity<Dim>::*member;
    bool record;
    Real cutoff;  ///< nodal mass below which a body is absent, kg
    Real dt;      ///< s
    int slots;    ///< partners per body: bodies, then planes
    std::vector<Vec<Dim>> plane_velocity;
    const GridGeometry<Dim>* geometry = nullptr;  ///< node positions, for the moments of the forces
    /// the nodes whose forces and work this rank sums (all in one process)
    NodeMask owned{};
    bool owns(Index I) const { return owned.contains(I); }
  };
  /// The contact correction at every candidate node: two-body nodes (eqs 5.2-5.8), nodes of three or more
  /// bodies, nodes behind a plane; then the force log of the step.
  void correct(StepContext<Dim>& ctx, VecU<Dim> NodeVelocity<Dim>::*member, bool record);
  /// Corrects body k at node I against v_cm with normal n and friction mu (eqs 5.5-5.8); records the
  /// force on k from `other` (a body, or body_count_ + plane). False if the body was not approaching.
  bool apply_correction(const CorrectionPass& pass, Index I, int k, int other, const Vec<Dim>& v_cm, const Vec<Dim>& n,
                        Real mu);
  /// Centre-of-mass velocity of the bodies at node I (eq. 5.3), or the rigid body's velocity.
  Vec<Dim> centre_of_mass_velocity(const CorrectionPass& pass, Index I, const std::vector<int>& present,
                                   int rigid) const;
  /// Two bodies a < b at node I, with the pair normal (and the particle gap, with onset particle_gap).
  bool correct_pair(const CorrectionPass& pass, Index I, int a, int b, const Vec<Dim>& v_cm);
  /// Three or more bodies at node I: each with its own normal, against the system or the rigid body.
  bool correct_bodies(const CorrectionPass& pass, Index I, const std::vector<int>& present, int rigid,
                      const Vec<Dim>& v_cm);
  /// The deformable bodies at node I against every plane the node is behind.
  bool correct_planes(const CorrectionPass& pass, Index I, const GridGeometry<Dim>& g, const std::vector<int>& present);
  /// Contact node count, onset time, impulses for the CSV and last_forces() of the step.
  void log_forces(const CorrectionPass& pass, Index corrected_nodes, Real t);
  Vec<Dim> rigid_velocity(int r, Real t) const;
  Vec<Dim> plane_velocity(int k, Real t) const;
  void write_forces(Real time);
  /// The pass's corrected-node count and work and, when it records the forces (`record`), their sums: over every
  /// rank in a distributed run; the work is then added to work_.
  Index reduce_step(Communicator* comm, Index corrected_nodes, bool record);

  std::vector<Body<Dim>>& bodies_;
  ContactSettings<Dim> settings_;
  int body_count_ = 0;
  std::vector<Grid<Dim>> body_grids_;  ///< one per body (Body::separate_grid points here)
  std::vector<int> rigid_of_;          ///< per body: index into settings_.rigid_bodies, or -1
  /// per body: its own face conditions (settings_.body_faces), or null: the scene's (StepContext::boundary)
  std::vector<std::shared_ptr<const GridBoundary<Dim>>> body_boundary_;
  std::vector<std::array<Expression, Dim>> rigid_velocity_, plane_velocity_;
  std::vector<Vec<Dim>> plane_point_;
  std::unique_ptr<ShapePasses<Dim>> passes_;
  // Per step
  std::vector<Index> candidates_;                 ///< nodes where two bodies meet or a body is behind a plane
  std::vector<std::uint8_t> is_candidate_;        ///< per node
  std::vector<std::vector<VecU<Dim>>> gradient_;  ///< per body, per node: mass gradient (eq. 5.12) or 5.11
  std::vector<std::vector<Real>> extent_;         ///< per body, per node: max of x.n + half size (gap)
  std::vector<std::vector<Real>> gap_upper_;      ///< per body, per node: max of -x.n + half size (gap)
  std::vector<VecU<Dim>> pair_normal_;            ///< per node: unit normal from the lower to the higher body
  /// Onset particle_gap: per (plane, body), per node behind the plane: max over the body's particles of
  /// -x_p.n + half their size; the body touches the plane there when it is >= -point.n.
  std::vector<std::vector<Real>> plane_reach_;
  std::vector<std::uint8_t> plane_flag_;  ///< scratch of plane_reach: the nodes behind the plane being scanned
  std::vector<VecU<Dim>> plane_normal_;   ///< scratch of plane_reach: -n of that plane at those nodes
  // Forces
  std::vector<Vec<Dim>> impulse_;  ///< per (body, other slot): impulse since the last CSV row, N s
  std::vector<Real> impulse_n_;
  std::vector<PairForce<Dim>> last_forces_;
  std::vector<Vec<Dim>> step_force_;  ///< per (body, other slot): force of this step
  std::vector<Vec3> step_moment_;     ///< per (body, other slot): sum of x_I x f_I of this step, N m
  std::vector<Real> step_normal_;
  /// The three above as they are summed over the corrected nodes: exactly (exact_sum.hpp), so that they do
  /// not depend on the order of the nodes (nor, later, on the ranks that own them).
  struct StepSums {
    std::array<ExactSum, Dim> force;
    std::array<ExactSum, 3> moment;
    ExactSum normal;
  };
  std::vector<StepSums> step_sums_;
  CorrectionWork work_;
  /// The work of the corrections of the current pass, exactly (then reduced over the ranks and added to work_).
  ExactSum remapped_work_, start_work_;
  bool writes_files_ = true;  ///< false on every rank but 0 of a distributed run
  Real onset_time_ = -1;
  Index contact_nodes_last_ = 0;
  Real last_row_time_ = 0;
  std::ofstream csv_;  ///< opened at the first row
};

}  // namespace mpm::contact
