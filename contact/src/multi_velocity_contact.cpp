#include "mpm/contact/multi_velocity_contact.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "mpm/contact/contact_law.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/io/continued_file.hpp"
#include "mpm/schemes/local_damping.hpp"
#include "shape_passes.hpp"

namespace mpm::contact {
namespace {

constexpr std::uint8_t body_pair = 1;  // node where two or more bodies have mass
constexpr std::uint8_t behind_plane = 2;

template <int Dim>
Vec<Dim> unit_or_zero(const Vec<Dim>& v) {
  const Real n = v.norm();
  return n > 0 ? Vec<Dim>(v / n) : Vec<Dim>::Zero();
}

template <int Dim>
std::array<Expression, Dim> expressions(const std::array<std::string, Dim>& text) {
  return [&]<std::size_t... d>(std::index_sequence<d...>) {
    return std::array<Expression, Dim>{Expression(text[d], {"t"})...};
  }
  (std::make_index_sequence<Dim>{});
}

template <int Dim>
Vec<Dim> evaluate(const std::array<Expression, Dim>& e, Real t) {
  Vec<Dim> v;
  for (int d = 0; d < Dim; ++d) v[d] = e[d](0, 0, 0, t);
  return v;
}

/// Cell-centred density of eq. 5.9 with the quadratic B-spline S^2 of eq. 5.10 (bounds as corrected in
/// docs/errata.md #9: +-h/2, +-3h/2), then the nodal normals of eq. 5.11 with the hat-function gradients at
/// the centres of the cells around each node. Serial: an alternative to eq. 5.12, selected by the scene.
template <int Dim>
void density_normals(const Body<Dim>& body, const GridGeometry<Dim>& g, const std::vector<Index>& nodes,
                     std::vector<VecU<Dim>>& out, std::vector<Real>& density) {
  std::array<int, Dim> cells{};
  Index n_cells = 1;
  for (int d = 0; d < Dim; ++d) {
    cells[d] = g.cells(d);
    n_cells *= cells[d];
  }
  density.assign(n_cells, 0);
  const auto& p = body.particles;
  const Real inv_volume = 1 / g.cell_volume();
  const bool axisymmetric = g.coordinates == Coordinates::axisymmetric;  // the meridian density m_p / r_p
  for (Index i = 0; i < p.size(); ++i) {
    int base[Dim];
    Real w[Dim][3];
    for (int d = 0; d < Dim; ++d) {
      const Real xi = (p.x[i][d] - g.origin[d]) * g.inv_h[d] - 0.5;  // in cell-centre units
      base[d] = static_cast<int>(std::floor(xi + 0.5)) - 1;
      for (int k = 0; k < 3; ++k) {
        const Real r = std::abs(xi - (base[d] + k));
        w[d][k] = r < 0.5 ? 0.75 - r * r : (r < 1.5 ? 0.5 * (1.5 - r) * (1.5 - r) : 0);
      }
    }
    const int combos = Dim == 1 ? 3 : (Dim == 2 ? 9 : 27);
    for (int c = 0; c < combos; ++c) {
      int rest = c;
      Index linear = 0, stride = 1;
      Real weight = (axisymmetric ? p.mass[i] / p.x[i][0] : p.mass[i]) * inv_volume;
      bool inside = true;
      for (int d = 0; d < Dim; ++d) {
        const int k = rest % 3, idx = base[d] + k;
        rest /= 3;
        inside = inside && idx >= 0 && idx < cells[d];
        weight *= w[d][k];
        linear += stride * idx;
        stride *= cells[d];
      }
      if (inside) density[linear] += weight;
    }
  }
  for (const Index I : nodes) {
    const auto ijk = g.node_indices(I);
    Vec<Dim> n = Vec<Dim>::Zero();
    const int corners = 1 << Dim;
    for (int c = 0; c < corners; ++c) {
      Index linear = 0, stride = 1;
      bool inside = true;
      int side[Dim];
      for (int d = 0; d < Dim; ++d) {
        side[d] = (c >> d) & 1 ? 1 : -1;  // cell above (+1) or below (-1) the node on axis d
        const int idx = ijk[d] + (side[d] > 0 ? 0 : -1);
        inside = inside && idx >= 0 && idx < cells[d];
        linear += stride * idx;
        stride *= cells[d];
      }
      if (!inside) continue;
      // grad phi_I at the cell centre: d/dx_d of prod (1 - |x - x_I|/h) = -side_d / h_d * (1/2)^(Dim-1)
      for (int d = 0; d < Dim; ++d) n[d] += density[linear] * (-side[d] * g.inv_h[d]) * std::pow(0.5, Dim - 1);
    }
    out[I] = n;
  }
}

}  // namespace

template <int Dim>
MultiVelocityContact<Dim>::MultiVelocityContact(const GridGeometry<Dim>& grid, std::vector<Body<Dim>>& bodies,
                                                const std::string& shape_function, ContactSettings<Dim> settings)
    : bodies_(bodies), settings_(std::move(settings)), body_count_(static_cast<int>(bodies.size())) {
  passes_ = make_shape_passes<Dim>(shape_function, grid.coordinates);
  body_grids_.reserve(body_count_);  // Body::separate_grid points into body_grids_: no reallocation after this
  for (int k = 0; k < body_count_; ++k) {
    body_grids_.emplace_back(grid);
    bodies_[k].separate_grid = &body_grids_[k];
  }
  if (settings_.friction.size() != static_cast<std::size_t>(body_count_ * body_count_))
    settings_.friction.assign(body_count_ * body_count_, 0);
  rigid_of_.assign(body_count_, -1);
  body_boundary_.resize(body_count_);
  for (const auto& own : settings_.body_faces) body_boundary_[own.body] = own.boundary;
  for (std::size_t r = 0; r < settings_.rigid_bodies.size(); ++r) {
    const auto& rb = settings_.rigid_bodies[r];
    rigid_of_[rb.body] = static_cast<int>(r);
    rigid_velocity_.push_back(expressions<Dim>(rb.velocity));
    // Rigid particles start with the prescribed velocity (their kinetic energy is then constant).
    const Vec<Dim> v0 = rigid_velocity(static_cast<int>(r), 0);
    for (auto& v : bodies_[rb.body].particles.v) v = v0;
  }
  for (const auto& plane : settings_.planes) {
    plane_velocity_.push_back(expressions<Dim>(plane.velocity));
    plane_point_.push_back(plane.point);
  }
  const Index nodes = grid.node_count();
  is_candidate_.assign(nodes, 0);
  gradient_.assign(body_count_, std::vector<VecU<Dim>>(nodes, VecU<Dim>::Zero()));
  if (settings_.onset == Onset::particle_gap)
    extent_.assign(body_count_, std::vector<Real>(nodes, -std::numeric_limits<Real>::infinity()));
  pair_normal_.assign(nodes, VecU<Dim>::Zero());
  const std::size_t slots = body_count_ * (body_count_ + settings_.planes.size());
  impulse_.assign(slots, Vec<Dim>::Zero());
  impulse_n_.assign(slots, 0);
  step_force_.assign(slots, Vec<Dim>::Zero());
  step_moment_.assign(slots, Vec3::Zero());
  step_normal_.assign(slots, 0);
  step_sums_.assign(slots, {});
}

template <int Dim>
MultiVelocityContact<Dim>::~MultiVelocityContact() {
  for (auto& b : bodies_) b.separate_grid = nullptr;
}

template <int Dim>
Vec<Dim> MultiVelocityContact<Dim>::rigid_velocity(int r, Real t) const {
  return evaluate<Dim>(rigid_velocity_[r], t);
}
template <int Dim>
Vec<Dim> MultiVelocityContact<Dim>::plane_velocity(int k, Real t) const {
  return evaluate<Dim>(plane_velocity_[k], t);
}

template <int Dim>
void MultiVelocityContact<Dim>::after_p2g(StepContext<Dim>& ctx) {
  // The shared grid holds the sum of the bodies' fields (for grid output and any reader of the system), on the
  // nodes this rank's particles reach (all in one process).
  auto& shared = ctx.grid;
  for_each_node_block(shared.size(), ctx.active_nodes, 1 << 12, [&](Index begin, Index end) {
    for (Index i = begin; i != end; ++i) {
      NodeRecord<Dim>& s = shared.node[i];
      for (int k = 0; k < body_count_; ++k) {
        const NodeRecord<Dim>& o = body_grids_[k].node[i];
        s.mass += o.mass;
        s.momentum += o.momentum;
        s.force += o.force;
      }
    }
  });
  if (ctx.boundary.has_traction()) share_tractions(ctx);
  find_candidates(ctx);
}

template <int Dim>
void MultiVelocityContact<Dim>::share_tractions(StepContext<Dim>& ctx) {
  // GridBoundary ran before the bodies' fields were summed, when the shared grid had no mass: its tractions are added
  // here, to the system's field as without contact, and to the deformable bodies' fields in proportion to their
  // masses at the node (docs/theory.md §11, "Face tractions").
  auto& shared = ctx.grid;
  ctx.boundary.traction_forces(ctx.time, ctx.active_nodes, [&](Index I, int c, Real force) {
    NodeRecord<Dim>& s = shared.node[I];
    if (!(s.mass > 0)) return;
    s.force[c] += force;
    Real deformable = 0;
    for (int k = 0; k < body_count_; ++k)
      if (rigid_of_[k] < 0) deformable += body_grids_[k].node[I].mass;
    if (!(deformable > 0)) return;  // a rigid body alone: it moves as prescribed whatever the force
    for (int k = 0; k < body_count_; ++k)
      if (NodeRecord<Dim>& own = body_grids_[k].node[I]; rigid_of_[k] < 0 && own.mass > 0)
        own.force[c] += force * (own.mass / deformable);
  });
}

template <int Dim>
void MultiVelocityContact<Dim>::find_candidates(StepContext<Dim>& ctx) {
  const auto& g = ctx.grid.geometry;
  const Real cutoff = ctx.settings.mass_cutoff;
  for (const Index I : candidates_) is_candidate_[I] = 0;
  candidates_.clear();
  // The nodes the particles reach (StepContext::active_nodes): a body has no mass anywhere else. In ascending order.
  const Index nodes = g.node_count();
  for_each_node_in_order(nodes, ctx.active_nodes, [&](Index I) {
    int present = 0, deformable = 0;
    for (int k = 0; k < body_count_; ++k)
      if (body_grids_[k].node[I].mass > cutoff) {
        ++present;
        deformable += rigid_of_[k] < 0;
      }
    std::uint8_t flag = present >= 2 && deformable >= 1 ? body_pair : 0;
    if (deformable > 0 && !plane_point_.empty()) {
      const Vec<Dim> x = g.node_position(g.node_indices(I));
      for (std::size_t P = 0; P < plane_point_.size(); ++P)
        if ((x - plane_point_[P]).dot(settings_.planes[P].normal) <= 0) flag |= behind_plane;
    }
    if (flag) {
      is_candidate_[I] = flag;
      candidates_.push_back(I);
    }
  });
  if (settings_.onset == Onset::particle_gap) plane_reach(g, ctx.comm);
  bool pairs = false;
  for (const Index I : candidates_) pairs |= (is_candidate_[I] & body_pair) != 0;
  // the passes below exchange ghost nodes: every rank takes them when any has a pair
  if (ctx.comm) pairs = ctx.comm->any(pairs);
  if (!pairs) return;
  // Normals of every body (eq. 5.12 or 5.9-5.11), then the pair normal at two-body nodes.
  std::vector<Real> density;
  for (int k = 0; k < body_count_; ++k) {
    auto& grad = gradient_[k];
    if (settings_.normals == NormalMethod::mass_gradient) {
      std::memset(static_cast<void*>(grad.data()), 0, grad.size() * sizeof(VecU<Dim>));
      passes_->mass_gradient(bodies_[k], g, grad);
    } else {
      density_normals<Dim>(bodies_[k], g, candidates_, grad, density);
    }
    // On the axis of an axisymmetric scene the normal is axial by symmetry; the one-sided stencil there (no
    // particles at r < 0) would tilt it, and the correction would then push the axis nodes radially.
    if (g.coordinates == Coordinates::axisymmetric)
      for (const Index I : candidates_)
        if (g.node_indices(I)[0] == 0) grad[I][0] = 0;
  }
  for (const Index I : candidates_) {
    if (!(is_candidate_[I] & body_pair)) continue;
    int a = -1, b = -1, count = 0;
    for (int k = 0; k < body_count_; ++k)
      if (body_grids_[k].node[I].mass > cutoff) {
        (count == 0 ? a : b) = k;
        ++count;
      }
    if (count != 2) continue;  // three or more bodies: each uses its own normal
    const Vec<Dim> na = unit_or_zero<Dim>(gradient_[a][I]), nb = unit_or_zero<Dim>(gradient_[b][I]);
    // Equal and opposite normals (momentum is then conserved exactly, Bardenhagen et al. 2001); a rigid
    // body imposes its own (review §5.1.5).
    Vec<Dim> n;
    if (rigid_of_[a] >= 0)
      n = na;
    else if (rigid_of_[b] >= 0)
      n = -nb;
    else
      n = unit_or_zero<Dim>(na - nb);
    if (n.squaredNorm() == 0) n = na.squaredNorm() > 0 ? na : Vec<Dim>(-nb);
    pair_normal_[I] = n;
  }
  if (settings_.onset != Onset::particle_gap) return;
  for (int k = 0; k < body_count_; ++k)
    for (const Index I : candidates_) extent_[k][I] = -std::numeric_limits<Real>::infinity();
  // Extents along the pair normal: of the lower-numbered body along +n, of the other along -n. Each body
  // is scanned with both signs; at a node only the one matching its place in the pair is read.
  for (int k = 0; k < body_count_; ++k)
    passes_->extents(bodies_[k], g, is_candidate_.data(), pair_normal_.data(), 1, extent_[k]);
  // A second array per body would double the memory; instead the upper body's extent is recomputed with
  // sign -1 into a scratch copy.
  gap_upper_.resize(body_count_);
  for (int k = 0; k < body_count_; ++k) {
    gap_upper_[k].assign(extent_[k].size(), -std::numeric_limits<Real>::infinity());
    passes_->extents(bodies_[k], g, is_candidate_.data(), pair_normal_.data(), -1, gap_upper_[k]);
  }
}

template <int Dim>
void MultiVelocityContact<Dim>::plane_reach(const GridGeometry<Dim>& g, Communicator* comm) {
  const std::size_t planes = settings_.planes.size();
  if (planes == 0) return;
  const Index nodes = g.node_count();
  plane_flag_.assign(nodes, 0);
  plane_normal_.assign(nodes, VecU<Dim>::Zero());
  plane_reach_.resize(planes * body_count_);
  for (std::size_t P = 0; P < planes; ++P) {
    const Vec<Dim> n = settings_.planes[P].normal;
    std::vector<Index> behind;
    for (const Index I : candidates_)
      if ((is_candidate_[I] & behind_plane) && (g.node_position(g.node_indices(I)) - plane_point_[P]).dot(n) <= 0) {
        plane_flag_[I] = 1;  // the bit extents() scans
        plane_normal_[I] = -n;
        behind.push_back(I);
      }
    // the extents pass exchanges ghost nodes: every rank takes it when any has a node behind the plane
    const bool any_behind = comm ? comm->any(!behind.empty()) : !behind.empty();
    for (int k = 0; k < body_count_; ++k) {
      auto& reach = plane_reach_[P * body_count_ + k];
      reach.assign(nodes, -std::numeric_limits<Real>::infinity());
      if (rigid_of_[k] < 0 && any_behind)
        passes_->extents(bodies_[k], g, plane_flag_.data(), plane_normal_.data(), 1, reach);
    }
    for (const Index I : behind) plane_flag_[I] = 0;
  }
}

template <int Dim>
void MultiVelocityContact<Dim>::body_velocities(StepContext<Dim>& ctx, GridStage stage) {
  const Real cutoff = ctx.settings.mass_cutoff, dt = ctx.dt, damping = ctx.settings.damping;
  const Vec<Dim> gravity = ctx.settings.gravity;
  const auto deformable_fields = [&](auto&& visit) {
    for (int j = 0; j < body_count_; ++j)
      if (rigid_of_[j] < 0) visit(std::as_const(body_grids_[j]));
  };
  const Real t = stage == GridStage::mapped ? ctx.time : ctx.time + ctx.dt;
  auto member = stage == GridStage::updated ? &NodeVelocity<Dim>::updated : &NodeVelocity<Dim>::mapped;
  for (int k = 0; k < body_count_; ++k) {
    Grid<Dim>& own = body_grids_[k];
    if (rigid_of_[k] >= 0) {  // rigid: the prescribed velocity on every node it touches (Alg. 4)
      const VecU<Dim> v = rigid_velocity(rigid_of_[k], t);
      for_each_node_block(own.size(), ctx.active_nodes, 1 << 12, [&](Index begin, Index end) {
        for (Index i = begin; i != end; ++i)
          own.velocity[i].*member = own.node[i].mass > cutoff ? v : VecU<Dim>::Zero();
      });
      continue;
    }
    for_each_node_block(own.size(), ctx.active_nodes, 1 << 12, [&](Index begin, Index end) {
      for (Index i = begin; i != end; ++i) {
        const NodeRecord<Dim>& n = own.node[i];
        NodeVelocity<Dim>& v = own.velocity[i];
        if (!(n.mass > cutoff)) {
          v.*member = VecU<Dim>::Zero();
          continue;
        }
        const Real inv_m = 1 / n.mass;
        if (stage == GridStage::updated && damping > 0)  // eq. 5.1 with the local damping of the bodies' sum, eq. 2.74
          v.updated = (n.momentum + dt * (n.force + n.mass * gravity +
                                          n.mass * kernels::shared_damping_acceleration<Dim>(
                                                       i, gravity, cutoff, damping, deformable_fields))) *
                      inv_m;
        else if (stage == GridStage::updated)  // eq. 5.1: v~ = (mv + dt (f + m g)) / m
          v.updated = (n.momentum + dt * (n.force + n.mass * gravity)) * inv_m;
        else
          v.mapped = n.momentum * inv_m;
      }
    });
    // The body's own face conditions (contact.body_boundaries) instead of the scene's, if it has them.
    const GridBoundary<Dim>& boundary = body_boundary_[k] ? *body_boundary_[k] : ctx.boundary;
    if (!boundary.empty()) boundary.apply(own.velocity, member, t, ctx.active_nodes);
  }
}

template <int Dim>
void MultiVelocityContact<Dim>::on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) {
  body_velocities(ctx, stage);
  // v^t is left as mapped: the FLIP increment v~ - v^t carries the contact impulse to the particles.
  if (stage == GridStage::mapped) return;
  // MUSL's re-mapped velocity only gives the strain rate: correcting it between two deformable bodies changes the
  // strain energy but no particle's momentum (docs/theory.md §11, "Energy"), so by default each keeps its own.
  // Against a plane or a rigid body it is still corrected: like a boundary condition (also applied to the re-mapped
  // velocity), the prescribed motion then enters the strain rate (the platen's reaction, test_rigid_platen.cpp).
  const bool record = stage == GridStage::updated;
  const auto member = stage == GridStage::updated ? &NodeVelocity<Dim>::updated : &NodeVelocity<Dim>::mapped;
  correct(ctx, member, record);
  // A body with face conditions of its own has them again after the correction: at a node it shares with another
  // body's mass (a clamped base beside the water) the correction moved the held node, and with FLIP the increment
  // then carried that motion into the body (the FSI example's obstacle gained 14 J by 0.24 s, 23% of E0). Bodies
  // on the scene's conditions keep the order they had (their results unchanged, bit for bit).
  for (int k = 0; k < body_count_; ++k)
    if (body_boundary_[k] && !body_boundary_[k]->empty())
      body_boundary_[k]->apply(body_grids_[k].velocity, member, ctx.time + ctx.dt);
}

template <int Dim>
void MultiVelocityContact<Dim>::correct(StepContext<Dim>& ctx, VecU<Dim> NodeVelocity<Dim>::*member, bool record) {
  const Real t = ctx.time + ctx.dt;
  CorrectionPass pass{
      member, record, ctx.settings.mass_cutoff, ctx.dt, body_count_ + static_cast<int>(settings_.planes.size()), {}};
  pass.plane_velocity.resize(settings_.planes.size());
  pass.geometry = &ctx.grid.geometry;
  pass.owned = ctx.owned_nodes;
  for (std::size_t P = 0; P < pass.plane_velocity.size(); ++P)
    pass.plane_velocity[P] = plane_velocity(static_cast<int>(P), t);
  if (record) step_sums_.assign(step_force_.size(), {});
  Index corrected_nodes = 0;
  std::vector<int> present;
  for (const Index I : candidates_) {
    const std::uint8_t flag = is_candidate_[I];
    present.clear();
    for (int k = 0; k < body_count_; ++k)
      if (body_grids_[k].node[I].mass > pass.cutoff) present.push_back(k);
    bool corrected = false;
    if ((flag & body_pair) && present.size() >= 2) {
      int rigid = -1;
      for (const int k : present)
        if (rigid_of_[k] >= 0 && rigid < 0) rigid = k;
      const Vec<Dim> v_cm = centre_of_mass_velocity(pass, I, present, rigid);
      if (present.size() == 2)
        corrected = correct_pair(pass, I, present[0], present[1], v_cm);
      else
        corrected = correct_bodies(pass, I, present, rigid, v_cm);
    }
    if (flag & behind_plane) corrected = correct_planes(pass, I, ctx.grid.geometry, present) || corrected;
    corrected_nodes += corrected && pass.owns(I);
  }
  corrected_nodes = reduce_step(ctx.comm, corrected_nodes, record);
  if (!record) return;
  for (std::size_t s = 0; s < step_force_.size(); ++s) {
    for (int d = 0; d < Dim; ++d) step_force_[s][d] = step_sums_[s].force[d].value();
    for (int d = 0; d < 3; ++d) step_moment_[s][d] = step_sums_[s].moment[d].value();
    step_normal_[s] = step_sums_[s].normal.value();
  }
  log_forces(pass, corrected_nodes, t);
}

template <int Dim>
bool MultiVelocityContact<Dim>::apply_correction(const CorrectionPass& pass, Index I, int k, int other,
                                                 const Vec<Dim>& v_cm, const Vec<Dim>& n, Real mu) {
  NodeVelocity<Dim>& nv = body_grids_[k].velocity[I];
  Vec<Dim> v = nv.*pass.member;
  const Vec<Dim> before = v;
  // The partner's velocity at the start of the step: a body's own v^t, a plane's velocity.
  const bool rigid_partner = other >= body_count_ || rigid_of_[other] >= 0;
  const Vec<Dim> partner_start =
      other >= body_count_ ? pass.plane_velocity[other - body_count_] : Vec<Dim>(body_grids_[other].velocity[I].mapped);
  if (!pass.record && !settings_.correct_remapped && !rigid_partner) return false;
  // release_on_start: a node whose two deformable bodies separate at v^t is not corrected (the correction's work
  // J.(v^t_k - v^t_partner) would be positive, CorrectionWork::start_velocity). Planes and rigid bodies keep the
  // paper's test: a resting contact there has v^t . n = 0 up to round-off and would chatter.
  if (pass.record && settings_.release_on_start && !rigid_partner &&
      !((Vec<Dim>(nv.mapped) - partner_start).dot(n) > 0))
    return false;
  if (!correct_velocity<Dim>(v, v_cm, n, mu)) return false;
  nv.*pass.member = v;
  if (!pass.owns(I)) return true;  // another rank sums this node's force and work
  const Real m = body_grids_[k].node[I].mass;
  if (!pass.record) {  // the re-mapped velocity: only the strain rate sees the change
    remapped_work_ += -pass.dt * Vec<Dim>(body_grids_[k].node[I].force).dot(v - before);
    return true;
  }
  const Vec<Dim> impulse = m * (v - before);
  start_work_ += impulse.dot(Vec<Dim>(nv.mapped) - (rigid_partner ? partner_start : Vec<Dim>::Zero()));
  const Vec<Dim> f = impulse / pass.dt;
  StepSums& sums = step_sums_[k * pass.slots + other];
  for (int d = 0; d < Dim; ++d) sums.force[d] += f[d];
  Vec3 x3 = Vec3::Zero(), f3 = Vec3::Zero();
  x3.template head<Dim>() = pass.geometry->node_position(pass.geometry->node_indices(I));
  f3.template head<Dim>() = f;
  const Vec3 moment = x3.cross(f3);
  for (int d = 0; d < 3; ++d) sums.moment[d] += moment[d];
  sums.normal += -f.dot(n);
  return true;
}

template <int Dim>
Vec<Dim> MultiVelocityContact<Dim>::centre_of_mass_velocity(const CorrectionPass& pass, Index I,
                                                            const std::vector<int>& present, int rigid) const {
  // infinite mass: the centre of mass moves with the rigid body (review §5.1.5)
  if (rigid >= 0) return body_grids_[rigid].velocity[I].*pass.member;
  Vec<Dim> v_cm = Vec<Dim>::Zero();  // eq. 5.3
  Real m = 0;
  for (const int k : present) {
    v_cm += body_grids_[k].node[I].mass * Vec<Dim>(body_grids_[k].velocity[I].*pass.member);
    m += body_grids_[k].node[I].mass;
  }
  v_cm /= m;
  return v_cm;
}

template <int Dim>
bool MultiVelocityContact<Dim>::correct_pair(const CorrectionPass& pass, Index I, int a, int b, const Vec<Dim>& v_cm) {
  if (settings_.onset == Onset::particle_gap && !(-(extent_[a][I] + gap_upper_[b][I]) <= 0))
    return false;  // a gap between the particles' surfaces along n
  const Vec<Dim> n = pair_normal_[I];
  const Real mu = settings_.friction[a * body_count_ + b];
  bool corrected = false;
  if (rigid_of_[a] < 0) corrected = apply_correction(pass, I, a, b, v_cm, n, mu) || corrected;
  if (rigid_of_[b] < 0) corrected = apply_correction(pass, I, b, a, v_cm, -n, mu) || corrected;
  return corrected;
}

template <int Dim>
bool MultiVelocityContact<Dim>::correct_bodies(const CorrectionPass& pass, Index I, const std::vector<int>& present,
                                               int rigid, const Vec<Dim>& v_cm) {
  // Three or more bodies: each against the system (or the rigid body), with its own normal and the friction
  // of its pair with the heaviest other body at the node.
  const Vec<Dim> rigid_n = rigid >= 0 ? unit_or_zero<Dim>(gradient_[rigid][I]) : Vec<Dim>::Zero();
  bool corrected = false;
  for (const int k : present) {
    if (rigid_of_[k] >= 0) continue;
    int other = rigid;
    if (other < 0) {
      Real heaviest = -1;
      for (const int j : present)
        if (j != k && body_grids_[j].node[I].mass > heaviest) heaviest = body_grids_[j].node[I].mass, other = j;
    }
    const Vec<Dim> n = rigid >= 0 ? Vec<Dim>(-rigid_n) : unit_or_zero<Dim>(gradient_[k][I]);
    corrected = apply_correction(pass, I, k, other, v_cm, n, settings_.friction[k * body_count_ + other]) || corrected;
  }
  return corrected;
}

template <int Dim>
bool MultiVelocityContact<Dim>::correct_planes(const CorrectionPass& pass, Index I, const GridGeometry<Dim>& g,
                                               const std::vector<int>& present) {
  const Vec<Dim> x = g.node_position(g.node_indices(I));
  bool corrected = false;
  for (std::size_t P = 0; P < settings_.planes.size(); ++P) {
    const auto& plane = settings_.planes[P];
    if ((x - plane_point_[P]).dot(plane.normal) > 0) continue;
    for (const int k : present) {
      if (rigid_of_[k] >= 0) continue;
      // particle_gap: only where the body's particles reach the plane (surface = centre - half the size along n)
      if (settings_.onset == Onset::particle_gap &&
          !(plane_reach_[P * body_count_ + k][I] >= -Vec<Dim>(plane_point_[P]).dot(plane.normal)))
        continue;
      corrected = apply_correction(pass, I, k, body_count_ + static_cast<int>(P), pass.plane_velocity[P], -plane.normal,
                                   plane.friction) ||
                  corrected;
    }
  }
  return corrected;
}

template <int Dim>
Index MultiVelocityContact<Dim>::reduce_step(Communicator* comm, Index corrected_nodes, bool record) {
  if (comm) {
    // one message: the pass's two works, then (recording) every slot's force, moment and normal sums
    std::vector<ExactSum> sums{remapped_work_, start_work_};
    if (record)
      for (const StepSums& s : step_sums_) {
        sums.insert(sums.end(), s.force.begin(), s.force.end());
        sums.insert(sums.end(), s.moment.begin(), s.moment.end());
        sums.push_back(s.normal);
      }
    comm->sum(sums);
    remapped_work_ = sums[0];
    start_work_ = sums[1];
    std::size_t at = 2;
    if (record)
      for (StepSums& s : step_sums_) {
        for (auto& f : s.force) f = sums[at++];
        for (auto& m : s.moment) m = sums[at++];
        s.normal = sums[at++];
      }
    std::int64_t count[] = {static_cast<std::int64_t>(corrected_nodes)};
    comm->sum(count);
    corrected_nodes = static_cast<Index>(count[0]);
  }
  work_.remapped += remapped_work_.value();
  work_.start_velocity += start_work_.value();
  remapped_work_ = {};
  start_work_ = {};
  return corrected_nodes;
}

template <int Dim>
void MultiVelocityContact<Dim>::log_forces(const CorrectionPass& pass, Index corrected_nodes, Real t) {
  contact_nodes_last_ = corrected_nodes;
  if (corrected_nodes > 0 && onset_time_ < 0) onset_time_ = t;
  for (std::size_t s = 0; s < step_force_.size(); ++s) {
    impulse_[s] += pass.dt * step_force_[s];
    impulse_n_[s] += pass.dt * step_normal_[s];
  }
  last_forces_.clear();
  for (int k = 0; k < body_count_; ++k)
    for (int o = 0; o < pass.slots; ++o) {
      const int s = k * pass.slots + o;
      if (step_force_[s].squaredNorm() == 0) continue;
      PairForce<Dim> f;
      f.body = k;
      f.other = o < body_count_ ? o : -1 - (o - body_count_);
      f.force = step_force_[s];
      f.normal = step_normal_[s];
      f.tangential = std::sqrt(std::max<Real>(0, f.force.squaredNorm() - f.normal * f.normal));
      last_forces_.push_back(f);
    }
}

template <int Dim>
std::vector<std::string> MultiVelocityContact<Dim>::reaction_partners() const {
  std::vector<std::string> names;
  for (const auto& plane : settings_.planes) names.push_back(plane.name);
  for (const auto& rigid : settings_.rigid_bodies) names.push_back(bodies_[rigid.body].name);
  return names;
}

template <int Dim>
Reaction<Dim> MultiVelocityContact<Dim>::last_reaction(int k) const {
  const int planes = static_cast<int>(settings_.planes.size());
  const int slots = body_count_ + planes;
  const int other = k < planes ? body_count_ + k : settings_.rigid_bodies[k - planes].body;
  Reaction<Dim> r;
  for (int b = 0; b < body_count_; ++b) {  // on every deformable body, in body order
    if (rigid_of_[b] >= 0) continue;
    r.force += step_force_[b * slots + other];
    r.first_moment += step_moment_[b * slots + other];
  }
  return r;
}

template <int Dim>
std::vector<std::string> MultiVelocityContact<Dim>::contact_partners() const {
  std::vector<std::string> names;
  for (int b = 0; b < body_count_; ++b) names.push_back(bodies_[b].name);
  for (const auto& plane : settings_.planes) names.push_back(plane.name);
  return names;
}

template <int Dim>
Reaction<Dim> MultiVelocityContact<Dim>::last_contact_force(int body, int partner) const {
  const int slots = body_count_ + static_cast<int>(settings_.planes.size());
  Reaction<Dim> r;
  for (int o = 0; o < slots; ++o) {  // in slot order: the same sum on every rank (each step_force_ is reduced)
    if (partner >= 0 && o != partner) continue;
    r.force += step_force_[body * slots + o];
    r.first_moment += step_moment_[body * slots + o];
  }
  return r;
}

template <int Dim>
void MultiVelocityContact<Dim>::end_of_step(StepContext<Dim>& ctx) {
  const Real t = ctx.time + ctx.dt;
  // Rigid particles keep exactly the prescribed velocity (the grid gives it up to round-off).
  for (std::size_t r = 0; r < settings_.rigid_bodies.size(); ++r) {
    const VecU<Dim> v = rigid_velocity(static_cast<int>(r), t);
    for (auto& vp : bodies_[settings_.rigid_bodies[r].body].particles.v) vp = v;
  }
  for (std::size_t P = 0; P < plane_point_.size(); ++P)  // midpoint rule for the plane's position
    plane_point_[P] += ctx.dt * plane_velocity(static_cast<int>(P), ctx.time + 0.5 * ctx.dt);
  if (!settings_.force_file.empty() && t - last_row_time_ >= settings_.force_interval * (1 - 1e-9)) write_forces(t);
}

template <int Dim>
void MultiVelocityContact<Dim>::write_forces(Real time) {
  if (!csv_.is_open() && writes_files_) {  // opened at the first row: building a simulation (mpm check) writes nothing
    const std::filesystem::path file(settings_.force_file);
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    csv_.open(file);
    if (!csv_) throw std::runtime_error("contact: cannot write the force file " + settings_.force_file);
    csv_ << "time,body,other,normal_force,tangential_force";
    const char* axis[] = {"x", "y", "z"};
    for (int d = 0; d < Dim; ++d) csv_ << ",force_" << axis[d];
    csv_ << '\n';
    csv_.precision(10);
  }
  const Real span = time - last_row_time_;
  last_row_time_ = time;
  if (!(span > 0)) return;
  const int slots = body_count_ + static_cast<int>(settings_.planes.size());
  auto name_of = [&](int o) { return o < body_count_ ? bodies_[o].name : settings_.planes[o - body_count_].name; };
  auto row = [&](const std::string& body, const std::string& other, const Vec<Dim>& impulse, Real normal) {
    const Vec<Dim> f = impulse / span;
    const Real fn = normal / span;
    const Real ft = std::sqrt(std::max<Real>(0, f.squaredNorm() - fn * fn));
    if (!writes_files_) return;  // rank 0 of a distributed run writes the rows (every rank holds the same sums)
    csv_ << time << ',' << body << ',' << other << ',' << fn << ',' << ft;
    for (int d = 0; d < Dim; ++d) csv_ << ',' << f[d];
    csv_ << '\n';
  };
  // Force on every deformable body from each partner, then the reaction on every rigid body and plane
  // (minus the sum of what it gave), which is what a platen's load cell would read.
  std::vector<Vec<Dim>> reaction(slots, Vec<Dim>::Zero());
  std::vector<Real> reaction_n(slots, 0);
  std::vector<bool> touched(slots, false);
  for (int k = 0; k < body_count_; ++k)
    for (int o = 0; o < slots; ++o) {
      const int s = k * slots + o;
      if (impulse_[s].squaredNorm() == 0) continue;
      row(bodies_[k].name, name_of(o), impulse_[s], impulse_n_[s]);
      reaction[o] -= impulse_[s];
      reaction_n[o] += impulse_n_[s];
      touched[o] = true;
      impulse_[s].setZero();
      impulse_n_[s] = 0;
    }
  for (int o = 0; o < slots; ++o) {
    const bool rigid = o >= body_count_ || rigid_of_[o] >= 0;
    if (rigid) row(name_of(o), "all", reaction[o], touched[o] ? reaction_n[o] : 0);
  }
  if (writes_files_) csv_.flush();
}

template <int Dim>
void MultiVelocityContact<Dim>::save_state(StateArchive& archive, const std::string& prefix) const {
  auto flat = [](const std::vector<Vec<Dim>>& v) {
    std::vector<Real> out;
    for (const auto& x : v) out.insert(out.end(), x.data(), x.data() + Dim);
    return out;
  };
  archive.put_values<Real>(prefix + "plane_point", flat(plane_point_), Dim);
  archive.put_values<Real>(prefix + "impulse", flat(impulse_), Dim);
  archive.put_values<Real>(prefix + "impulse_normal", impulse_n_);
  archive.put_number(prefix + "onset_time", onset_time_);
  archive.put_number(prefix + "last_row_time", last_row_time_);
  archive.put_integer(prefix + "contact_nodes_last", contact_nodes_last_);
  std::vector<int> pairs;
  std::vector<Real> forces;
  for (const auto& f : last_forces_) {
    pairs.insert(pairs.end(), {f.body, f.other});
    forces.insert(forces.end(), f.force.data(), f.force.data() + Dim);
    forces.insert(forces.end(), {f.normal, f.tangential});
  }
  archive.put_values<int>(prefix + "last_force_pairs", pairs, 2);
  archive.put_values<Real>(prefix + "last_forces", forces, Dim + 2);
  // The force CSV is flushed after every row group: its length on disk is what was written (nothing yet while
  // it is not open, whatever an older run left there).
  io::FileMark mark = io::mark_file(settings_.force_file.empty() ? "." : settings_.force_file);
  if (!csv_.is_open()) mark.bytes = 0;
  io::save_mark(archive, prefix + "force_file", mark);
}

template <int Dim>
void MultiVelocityContact<Dim>::restore_state(const StateArchive& archive, const std::string& prefix) {
  auto unflat = [](const std::vector<Real>& in, std::vector<Vec<Dim>>& out, const std::string& name) {
    if (in.size() != out.size() * Dim) throw ArchiveError(name + ": the checkpoint has another number of entries");
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = Eigen::Map<const Vec<Dim>>(in.data() + k * Dim);
  };
  unflat(archive.values<Real>(prefix + "plane_point"), plane_point_, prefix + "plane_point");
  unflat(archive.values<Real>(prefix + "impulse"), impulse_, prefix + "impulse");
  impulse_n_ = archive.values<Real>(prefix + "impulse_normal");
  if (impulse_n_.size() != impulse_.size()) throw ArchiveError(prefix + "impulse_normal: wrong number of entries");
  onset_time_ = archive.number(prefix + "onset_time");
  last_row_time_ = archive.number(prefix + "last_row_time");
  contact_nodes_last_ = archive.integer(prefix + "contact_nodes_last");
  const auto pairs = archive.values<int>(prefix + "last_force_pairs");
  const auto forces = archive.values<Real>(prefix + "last_forces");
  last_forces_.clear();
  for (std::size_t k = 0; 2 * k + 1 < pairs.size() && (k + 1) * (Dim + 2) <= forces.size(); ++k) {
    PairForce<Dim> f;
    f.body = pairs[2 * k];
    f.other = pairs[2 * k + 1];
    const Real* values = forces.data() + k * (Dim + 2);
    f.force = Eigen::Map<const Vec<Dim>>(values);
    f.normal = values[Dim];
    f.tangential = values[Dim + 1];
    last_forces_.push_back(f);
  }
  if (settings_.force_file.empty() || !writes_files_) return;
  const io::FileMark mark = io::load_mark(archive, prefix + "force_file");
  if (csv_.is_open()) csv_.close();
  io::continue_file(mark, settings_.force_file);
  if (mark.bytes == 0) return;  // the header comes with the first row
  csv_.open(settings_.force_file, std::ios::app);
  if (!csv_) throw std::runtime_error("contact: cannot write the force file " + settings_.force_file);
  csv_.precision(10);
}

template class MultiVelocityContact<1>;
template class MultiVelocityContact<2>;
template class MultiVelocityContact<3>;

}  // namespace mpm::contact
