#pragma once
/// \file transfer_kernels.hpp
/// The particle-grid transfers shared by the explicit schemes (review §2.5, Alg. 1-2). Each kernel is
/// short, templated on dimension and shape function, and has no virtual call inside its loops.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/grid/active_tiles.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/schemes/local_damping.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "mpm/shape/stencil.hpp"
#include "mpm/simulation/step_context.hpp"

namespace mpm::kernels {

/// Zeroes mass, momentum and force of every node (of `nodes`: StepContext::active_nodes).
template <int Dim>
void reset_grid(Grid<Dim>& grid, NodeRuns nodes = {}) {
  for_each_node_block(grid.size(), nodes, 1 << 14, [&](Index begin, Index end) {
    std::memset(static_cast<void*>(grid.node.data() + begin), 0, sizeof(NodeRecord<Dim>) * (end - begin));
  });
}

/// The nodal arrays a body's transfers use: its own (multi-velocity contact) or the shared grid.
template <int Dim>
inline Grid<Dim>& grid_of(Body<Dim>& body, Grid<Dim>& shared) {
  return body.separate_grid ? *body.separate_grid : shared;
}
template <int Dim>
inline const Grid<Dim>& grid_of(const Body<Dim>& body, const Grid<Dim>& shared) {
  return body.separate_grid ? *body.separate_grid : shared;
}

/// Zeroes the bodies' own nodal arrays (contact), when they have any.
template <int Dim>
void reset_own_grids(std::vector<Body<Dim>>& bodies, NodeRuns nodes = {}) {
  for (auto& body : bodies)
    if (body.separate_grid) reset_grid(*body.separate_grid, nodes);
}

/// Bins every body's particles by tile (a particle outside the grid trips the guard) and, in one process with
/// sparse tiles (ctx.active_tiles), makes ctx.active_nodes the nodes the particles of this step's and the previous
/// step's tiles reach (active_tiles.hpp). Before the grid is reset: the reset visits those nodes.
template <int Dim, class Shape>
void bin_bodies(StepContext<Dim>& ctx) {
  const auto& g = ctx.grid.geometry;
  for (auto& body : ctx.bodies) {
    bin_by_tile(body.particles, g, Shape::slab_cells, body.bins);
    if (body.bins.outside >= 0) ctx.guard_tripped = true;
  }
  if (!ctx.active_tiles) return;
  std::vector<const TileBins*> bins;
  bins.reserve(ctx.bodies.size());
  for (const auto& body : ctx.bodies) bins.push_back(&body.bins);
  // A dense update (a new tiling, after forget()) keeps the context's set: every node in one process, the rank's held
  // nodes in a distributed run.
  if (const NodeRuns nodes = ctx.active_tiles->update(
          make_tile_grid(g, Shape::slab_cells, Shape::slab_reach_below, Shape::slab_reach_above), bins);
      !nodes.all)
    ctx.active_nodes = nodes;
  // Memory follows the particles: the pages of the stretches the particles left go back to the system.
  for (const auto& [first, end] : ctx.active_tiles->left()) {
    ctx.grid.release_nodes(first, end);
    for (auto& body : ctx.bodies)
      if (body.separate_grid) body.separate_grid->release_nodes(first, end);
  }
}

/// The on-demand particle field "body_force" (acceleration b_p, m/s^2, set by a module before the step),
/// or nullptr: P2G adds f_I += phi_I m_p b_p (eq. 2.35) when it exists. Gravity is separate (m_I g).
template <int Dim>
const VecU<Dim>* body_force_of(const ParticleSet<Dim>& p) {
  return p.has_field(keys::body_force<Dim>) ? p.field(keys::body_force<Dim>).data() : nullptr;
}

/// The on-demand particle field "affine_velocity" (APIC's C_p, 1/s), or nullptr for PIC/FLIP transfers.
template <int Dim>
MatU<Dim>* affine_of(ParticleSet<Dim>& p) {
  return p.has_field(keys::affine_velocity<Dim>) ? p.field(keys::affine_velocity<Dim>).data() : nullptr;
}

/// APIC's affine matrix from nodal velocities (review eqs 5.37-5.38, Jiang et al. 2015):
/// C_p = B_p D_p^-1 with B_p = sum phi_I v_I (x_I - x_p)^T and D_p = sum phi_I (x_I - x_p)(x_I - x_p)^T.
/// For hat functions B_p D_p^-1 = sum v_I (x) grad phi_I exactly (D_p = diag f(1 - f) h^2 per axis), a
/// form that stays defined for a particle on a node, so it is used there.
template <int Dim, class Shape, class NodeVelocityOf>
Mat<Dim> affine_matrix(const Stencil<Dim, Shape>& st, NodeVelocityOf&& velocity_of) {
  Mat<Dim> B = Mat<Dim>::Zero(), D = Mat<Dim>::Zero(), G = Mat<Dim>::Zero();
  for (int a = 0; a < st.count; ++a) {
    const Vec<Dim> v = velocity_of(st.node[a]);
    const Vec<Dim> r = st.node_offset(a);
    for (int c = 0; c < Dim; ++c) G.col(c) += v * st.grad[a][c];
    B += st.w[a] * v * r.transpose();
    D += st.w[a] * r * r.transpose();
  }
  if constexpr (std::is_same_v<Shape, LinearHat>) {
    return G;
  } else {
    const Real scale = D.trace() / Dim;
    if (!(std::abs(D.determinant()) > 1e-12 * std::pow(scale, Dim))) return G;  // degenerate D
    return B * D.inverse();
  }
}

/// A node lighter than this fraction of a surface layer of particles is "nearly empty" for APIC with hats
/// (apic_light_node_mass, affine_matrix_of_trial).
inline constexpr Real apic_light_node_fraction = 0.05;

/// The mass below which a node is nearly empty for APIC with hats: apic_light_node_fraction of a surface layer of
/// particles, m_p n_face, with n_face = (h^dim / V_p0)^((dim-1)/dim) the particles per cell face (axisymmetric: the
/// meridian area V_p0 / (2 pi r_p) for V_p0). A node a distance d outside a flat face of such particles weighs
/// (1 - d/h) n_face m_p, so the rule takes the nodes with 1 - d/h < 0.05 in any dimension and at any particle
/// density. (A threshold of 0.1 m_p, the same in every dimension, takes them in 2D with 2 particles per cell per axis
/// but only below 0.025 in 3D and 0.011 with 3 per axis: a 10 mm steel cube striking a wall at 50 m/s then inverted a
/// particle of its top face at 22 us, hats, MUSL; docs/theory.md §2, velocity transfers.)
template <int Dim, class Coords = CartesianCoordinates>
Real apic_light_node_mass(const ParticleSet<Dim>& p, Index i, const GridGeometry<Dim>& g) {
  Real size = p.volume0[i];
  if constexpr (Coords::axisymmetric) size = axisym::meridian_area(size, p.x[i][0]);
  const Real per_cell = g.h.prod() / size;
  Real per_face = 1;
  if constexpr (Dim == 2) per_face = std::sqrt(per_cell);
  if constexpr (Dim == 3) per_face = std::cbrt(per_cell) * std::cbrt(per_cell);
  return apic_light_node_fraction * p.mass[i] * per_face;
}

/// The top of light_node_velocity's ramp, as a multiple of the light mass.
inline constexpr Real apic_light_node_ramp_top = 1.1;

/// The velocity a node brings into C_p (or PolyPIC's modes) with hats: the particle's own v_p below the light mass L
/// (apic_light_node_mass), the node's trial velocity v~_I from 1.1 L on, and a linear ramp between,
/// v_p + s (v~_I - v_p) with s = (m_I/L - 1)/0.1, so that the velocity gradient a particle takes is continuous in the
/// node masses. With a switch at L a 10 mm steel cube striking a contact plane that lies on a node line (3D, 2
/// particles per cell per axis, the defaults) spiked its strain energy to +29% of E0 for 4 steps as its bottom face
/// left the plane at d/h = 0.95, the switch point; with the ramp it never rises above E0. A wider ramp takes more
/// nodes without their gradient and dissipates more: PolyPIC's two disks lose 10.7% (ramp to 1.25 L) and 6.5% (to
/// 1.1 L) against 6.35% with the switch (docs/theory.md §2, velocity transfers).
template <int Dim>
inline Vec<Dim> light_node_velocity(Real m, Real light, const Vec<Dim>& v_p, const Vec<Dim>& v_trial) {
  if (m >= apic_light_node_ramp_top * light) return v_trial;
  if (m < light) return v_p;
  const Real s = (m / light - 1) / (apic_light_node_ramp_top - 1);
  return v_p + s * (v_trial - v_p);
}

/// C_p from the trial velocities v~_I = v_I^t + dt (f_I/m_I + g) (docs/theory.md §2, velocity transfers). For hats a
/// node enters C_p = sum v_I (x) grad phi_I with the weight grad phi_I, not phi_I: a nearly empty node at a free
/// surface (m_I = phi_I m_p -> 0) brings its trial velocity dt f_I/m_I unfiltered, the small-mass blow-up of
/// eq. 2.62 that PIC/FLIP see only through phi_I. Such a node (m_I < light_mass, apic_light_node_mass) enters C_p
/// with the particle's own velocity v_p, i.e. without a gradient, and a node up to 10% heavier with a blend
/// (light_node_velocity). Other shape functions weigh it by phi_I in B_p D_p^-1, which cancels the 1/m_I where
/// D_p is the interior one, and are left unchanged there. The boundary-modified quadratic B-spline is the hats in the
/// half cell next to a face (there D_dd falls below the interior moment h^2/4), so the columns of C_p along such axes
/// take the hats' filter (Shape::interior_second_moment): without it, APIC with quadratic B-splines gained energy in a
/// closed tank once the splash ran up the walls (Tait water inverted a particle, the incompressible fluid's energy rose
/// to 20 E0) and with it both lose energy at every output. (The same rule for the cubic fixed its tank too but moved
/// its affine transfer near the axis of an axisymmetric grid by 0.7% of a step's increment, not understood: the cubic
/// is left unchanged.) Filtering every column of such a particle let stacked blocks in contact sink 0.14 mm at the side
/// walls, 1.4% of a cell (docs/theory.md §2).
template <int Dim, class Shape, class NodeVelocityOf>
Mat<Dim> affine_matrix_of_trial(const Stencil<Dim, Shape>& st, const NodeRecord<Dim>* node, Real light_mass,
                                const Vec<Dim>& v_p, NodeVelocityOf&& velocity_of) {
  const auto filtered = [&](Index n) {
    return light_node_velocity<Dim>(node[n].mass, light_mass, v_p, Vec<Dim>(velocity_of(n)));
  };
  if constexpr (std::is_same_v<Shape, LinearHat>) {
    return affine_matrix(st, filtered);
  } else if constexpr (requires { Shape::interior_second_moment; }) {
    // Column d of B_p = sum phi_I v_I (x_I - x_p)^T takes the filtered velocities where D_dd falls below the interior
    // moment (the hat-like cells next to a face); the other columns keep every node's own. (D_p is diagonal where the
    // functions reproduce linear fields, so column d of C_p is then column d of B_p over D_dd.) D_p first, in
    // affine_matrix's order of summation, so that a particle away from the faces gets its bits.
    Mat<Dim> B = Mat<Dim>::Zero(), D = Mat<Dim>::Zero();
    for (int a = 0; a < st.count; ++a) {
      const Vec<Dim> r = st.node_offset(a);
      D += st.w[a] * r * r.transpose();
    }
    bool hat_like[Dim], any = false;
    for (int d = 0; d < Dim; ++d) {
      const Real h = st.offset[d][1] - st.offset[d][0];
      hat_like[d] = D(d, d) < Real(0.999) * Shape::interior_second_moment * h * h;
      any = any || hat_like[d];
    }
    if (any) {
      const Real scale = D.trace() / Dim;
      if (!(std::abs(D.determinant()) > 1e-12 * std::pow(scale, Dim))) return affine_matrix(st, filtered);  // on a face
    }
    for (int a = 0; a < st.count; ++a) {
      const Vec<Dim> v = velocity_of(st.node[a]), r = st.node_offset(a);
      if (!any) {
        B += st.w[a] * v * r.transpose();
        continue;
      }
      const Vec<Dim> v_light = filtered(st.node[a]);
      for (int d = 0; d < Dim; ++d) B.col(d) += st.w[a] * (hat_like[d] ? v_light : v) * r[d];
    }
    return B * D.inverse();
  } else {
    return affine_matrix(st, velocity_of);
  }
}

/// The on-demand particle field "polypic_modes" (PolyPIC's modes of degree two and more), or nullptr: APIC,
/// PIC/FLIP, 1D (where PolyPIC is APIC), and every shape function but the hats (the scene parser refuses them).
template <int Dim, class Shape>
keys::PolyModes<Dim>* polypic_of(ParticleSet<Dim>& p) {
  if constexpr (std::is_same_v<Shape, LinearHat> && Dim >= 2)  // PolyPIC has extra modes from 2D on
    return p.has_field(keys::polypic_modes<Dim>) ? p.field(keys::polypic_modes<Dim>).data() : nullptr;
  else
    return nullptr;
}

/// The axes (bit d: axis d) of PolyPIC's mode k of degree two and more, in the order of keys::PolyModes:
/// 2D xy; 3D xy, xz, yz, xyz.
template <int Dim>
constexpr unsigned polypic_mask(int k) {
  constexpr unsigned masks[4] = {0b011, 0b101, 0b110, 0b111};
  return masks[k];
}

/// The higher modes' part of a PolyPIC particle's velocity at offset r = x - x_p (m):
/// sum_k c_k prod_{d in S_k} r_d (Fu et al. 2017; docs/theory.md §2, velocity transfers).
template <int Dim>
inline Vec<Dim> polypic_higher_velocity(const keys::PolyModes<Dim>& modes, const Vec<Dim>& r) {
  Vec<Dim> u = Vec<Dim>::Zero();
  for (int k = 0; k < keys::polypic_extra_modes<Dim>; ++k) {
    Real basis = 1;
    for (int d = 0; d < Dim; ++d)
      if (polypic_mask<Dim>(k) >> d & 1u) basis *= r[d];
    u += basis * Vec<Dim>(modes[k]);
  }
  return u;
}

/// PolyPIC's modes of degree two and more from nodal velocities, for linear hats (Fu et al. 2017): the coefficient of
/// mode S is the mixed derivative c_S = sum_I v_I d^S phi_I(x_p) = sum_I v_I prod_{d in S} N'_d prod_{d not in S} N_d,
/// N'_d = -+1/h_d. With v_p = sum phi_I v_I and C_p = sum v_I (x) grad phi_I (the |S| <= 1 modes) the particle keeps
/// the exact Taylor expansion about x_p of the multilinear field sum_I v_I phi_I(x) of its cell: nothing is lost.
/// The 1D weight of node a on axis d is 1 + r/h for the lower node (r = -f h) and 1 - r/h for the upper one.
template <int Dim, class Shape, class NodeVelocityOf>
keys::PolyModes<Dim> polypic_modes(const Stencil<Dim, Shape>& st, const GridGeometry<Dim>& g,
                                   NodeVelocityOf&& velocity_of) {
  static_assert(std::is_same_v<Shape, LinearHat>, "PolyPIC's multilinear modes are those of the linear hats");
  keys::PolyModes<Dim> modes = keys::zero_poly_modes<Dim>();
  Real w[Dim][2], dw[Dim][2];
  for (int d = 0; d < Dim; ++d) {
    w[d][0] = 1 + st.offset[d][0] * g.inv_h[d];
    w[d][1] = 1 - st.offset[d][1] * g.inv_h[d];
    dw[d][0] = -g.inv_h[d];
    dw[d][1] = g.inv_h[d];
  }
  for (int a = 0; a < st.count; ++a) {
    const Vec<Dim> v = velocity_of(st.node[a]);
    for (int k = 0; k < keys::polypic_extra_modes<Dim>; ++k) {
      Real weight = 1;
      for (int d = 0; d < Dim; ++d) {
        const int side = a >> d & 1;
        weight *= (polypic_mask<Dim>(k) >> d & 1u) ? dw[d][side] : w[d][side];
      }
      modes[k] += weight * v;
    }
  }
  return modes;
}

/// polypic_modes from the trial velocities, a nearly empty node entering with the particle's own velocity v_p (a light
/// one with a blend, light_node_velocity) as in affine_matrix_of_trial (its trial velocity dt f_I/m_I would enter with
/// the weight 1/h^|S|, not phi_I).
template <int Dim, class Shape, class NodeVelocityOf>
keys::PolyModes<Dim> polypic_modes_of_trial(const Stencil<Dim, Shape>& st, const GridGeometry<Dim>& g,
                                            const NodeRecord<Dim>* node, Real light_mass, const Vec<Dim>& v_p,
                                            NodeVelocityOf&& velocity_of) {
  return polypic_modes(st, g, [&](Index n) {
    return light_node_velocity<Dim>(node[n].mass, light_mass, v_p, Vec<Dim>(velocity_of(n)));
  });
}

/// P2G (eqs 2.40, 2.43, 2.36): nodal mass, momentum and internal force f_I = -sum V_p sigma_p grad phi.
/// USF maps mass and momentum first and the force of the updated stress later: the two flags select.
/// Axisymmetric (Coords): V_p includes F_tt and f_rI gains the hoop term -V_p sigma_tt T_I (eq. G.2).
template <int Dim, class Shape, bool MassMomentum = true, bool Force = true, class Coords = CartesianCoordinates>
void particles_to_grid(Body<Dim>& body, Grid<Dim>& shared_grid) {
  Grid<Dim>& grid = grid_of(body, shared_grid);
  const auto& p = body.particles;
  const auto& g = grid.geometry;
  NodeRecord<Dim>* node = grid.node.data();
  const VecU<Dim>* body_force = Force ? body_force_of(p) : nullptr;
  const MatU<Dim>* affine = MassMomentum ? affine_of(body.particles) : nullptr;
  const keys::PolyModes<Dim>* poly = MassMomentum ? polypic_of<Dim, Shape>(body.particles) : nullptr;
  const Real* hoop_stretch = Coords::axisymmetric ? axisym::hoop_stretch_of(p) : nullptr;
  for_each_tile_coloured(body.bins, {HaloArray::of(grid.node)}, [&](const Index* index, Index count) {
    axisym::StencilFor<Dim, Shape, Coords> st;
    const ParticleDomain<Dim, Shape> domain(p);
    for (Index k = 0; k < count; ++k) {
      const Index i = index[k];
      st.compute(p.x[i], g, domain(i));
      const Real m = p.mass[i];
      const Vec<Dim> mv = m * p.v[i];
      Real V = p.volume0[i] * p.F[i].determinant();
      if constexpr (Coords::axisymmetric) V *= hoop_stretch[i];
      const Mat<Dim> vs = V * p.stress[i].block();
      [[maybe_unused]] const Real v_hoop = Coords::axisymmetric ? V * p.stress[i].c[2] : 0;  // V sigma_tt
      // Scalar loops on the packed record: Eigen's vectorised form mixes 128-bit stores with
      // overlapping 256-bit loads of the same record (a store-forwarding stall per node).
      Real mvs[Dim], vss[Dim][Dim];
      for (int r = 0; r < Dim; ++r) {
        mvs[r] = mv[r];
        for (int c = 0; c < Dim; ++c) vss[r][c] = vs(r, c);
      }
      // The APIC and PolyPIC tests are hoisted out of the node loop (a branch per node cost 15% on 3D cubic).
      auto scatter = [&](auto affine_tag, auto poly_tag) {
        constexpr bool with_affine = decltype(affine_tag)::value, with_poly = decltype(poly_tag)::value;
        Mat<Dim> mC;
        if constexpr (with_affine) mC = m * Mat<Dim>(affine[i]);
        for (int a = 0; a < st.count; ++a) {
          NodeRecord<Dim>& n = node[st.node[a]];
          const Real w = st.w[a];
          if constexpr (MassMomentum) {
            n.mass += w * m;
            if constexpr (with_affine) {  // APIC (eq. 5.37): m_p (v_p + C_p (x_I - x_p))
              Vec<Dim> extra = mC * st.node_offset(a);
              if constexpr (with_poly) extra += m * polypic_higher_velocity<Dim>(poly[i], st.node_offset(a));
              for (int r = 0; r < Dim; ++r) n.momentum[r] += w * (mvs[r] + extra[r]);
            } else {
              for (int r = 0; r < Dim; ++r) n.momentum[r] += w * mvs[r];
            }
          }
          if constexpr (Force) {
            for (int r = 0; r < Dim; ++r) {
              Real f = 0;
              for (int c = 0; c < Dim; ++c) f += vss[r][c] * st.grad[a][c];
              n.force[r] -= f;
            }
            if constexpr (Coords::axisymmetric) n.force[0] += axisym::hoop_force(v_hoop, st.hoop[a]);
          }
        }
      };
      if (poly)  // PolyPIC: m_p (v_p + C_p (x_I - x_p) + the higher modes at x_I - x_p)
        scatter(std::true_type{}, std::true_type{});
      else if (affine)
        scatter(std::true_type{}, std::false_type{});
      else
        scatter(std::false_type{}, std::false_type{});
      if (body_force)
        for (int a = 0; a < st.count; ++a)
          for (int r = 0; r < Dim; ++r) node[st.node[a]].force[r] += st.w[a] * m * body_force[i][r];
    }
  });
}

/// Nodal velocities before and after the momentum update (eqs 2.49-2.50 with the cut-off 2.63):
/// mapped = (mv)/m, updated = (mv + dt (f + m g))/m, with the local damping of eq. 2.74 when settings.damping > 0.
/// Nodes lighter than the cut-off get zero.
template <int Dim>
void update_grid_velocity(Grid<Dim>& grid, const TransferSettings<Dim>& s, Real dt, NodeRuns nodes = {}) {
  for_each_node_block(grid.size(), nodes, 1 << 12, [&](Index begin, Index end) {
    for (Index i = begin; i != end; ++i) {
      const NodeRecord<Dim>& n = grid.node[i];
      NodeVelocity<Dim>& v = grid.velocity[i];
      if (n.mass > s.mass_cutoff) {
        const Real inv_m = 1 / n.mass;
        v.mapped = n.momentum * inv_m;
        if (s.damping > 0)  // eq. 2.74
          v.updated = damped_velocity<Dim>(v.mapped, n.force + n.mass * s.gravity, n.mass, dt, s.damping);
        else
          v.updated = v.mapped + dt * (n.force * inv_m + s.gravity);
      } else {
        v.mapped.setZero();
        v.updated.setZero();
      }
    }
  });
}

/// F^{t+dt} = (I + dt L) F^t (eq. 2.55b); returns false when the result is not admissible
/// (det F <= 0 or not finite), which trips the stability guard.
template <int Dim>
inline bool update_deformation_gradient(MatU<Dim>& F, const Mat<Dim>& L, Real dt) {
  F = (Mat<Dim>::Identity() + dt * L) * F;
  const Real J = F.determinant();
  return J > 0 && std::isfinite(J);
}

/// Clamps x into [lower, upper] (GridBoundary::wall_lower/upper); NaN stays NaN for the guard.
template <int Dim>
inline void keep_inside_walls(VecU<Dim>& x, const Vec<Dim>& lower, const Vec<Dim>& upper) {
  for (int d = 0; d < Dim; ++d) {
    if (x[d] < lower[d]) x[d] = lower[d];
    if (x[d] > upper[d]) x[d] = upper[d];
  }
}

/// True when x is inside the box [lower, upper] the stability guard keeps particles in (false for NaN): the grid's,
/// open on an outflow face (GridBoundary::keep_lower/upper); axisymmetric: also off the axis, r > 0 (the hoop terms
/// divide by r).
template <int Dim, class Coords = CartesianCoordinates>
inline bool inside(const VecU<Dim>& x, const Vec<Dim>& lower, const Vec<Dim>& upper) {
  bool ok = true;
  for (int d = 0; d < Dim; ++d) ok = ok && x[d] >= lower[d] && x[d] <= upper[d];
  if constexpr (Coords::axisymmetric) ok = ok && x[0] > 0;
  return ok;
}

}  // namespace mpm::kernels
