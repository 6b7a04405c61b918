#pragma once
/// \file musl.hpp
/// Modified USL, double mapping (review §2.5.4, Algorithm 2): the particle velocities are updated from
/// the trial grid velocity, mapped back to the grid with the old weights (eq. 2.64) and the velocity
/// gradient is computed from that re-mapped velocity (eq. 2.65), which removes the small-mass problem.
/// The particle-velocity update and the second mapping are fused into one pass over the particles.
/// Axisymmetric (Coords): L_tt = sum T_I v_rI^{t+dt} of the re-mapped velocity, like L (axisymmetric.hpp).

#include "mpm/schemes/explicit_step.hpp"
#include "mpm/schemes/scheme.hpp"

namespace mpm {

template <int Dim, class Shape, class Coords = CartesianCoordinates>
class Musl final : public ShapedScheme<Dim, Shape> {
 public:
  std::string_view name() const override { return "musl"; }
  bool runs_distributed() const override { return true; }

  void advance(StepContext<Dim>& ctx) override {
    kernels::map_and_update_grid<Dim, Shape, Coords>(ctx);
    {
      PhaseTimer timer(ctx.profile, StepPhase::p2g);  // the second mapping (with the particle velocity update)
      clear_momentum(ctx.grid, ctx.active_nodes);
      for (auto& body : ctx.bodies)
        if (body.separate_grid) clear_momentum(*body.separate_grid, ctx.active_nodes);
      for (auto& body : ctx.bodies) update_velocity_and_remap(body, ctx);
    }
    {
      PhaseTimer timer(ctx.profile, StepPhase::grid_update);
      remapped_velocity(ctx);
    }
    kernels::transfer_and_update_stress(ctx, [&](Body<Dim>& body, Index begin, Index end, MatU<Dim>* L) {
      return update_position_and_deformation(body, ctx, begin, end, L);
    });
  }

 private:
  static void clear_momentum(Grid<Dim>& grid, NodeRuns nodes) {
    for_each_node_block(grid.size(), nodes, 1 << 14, [&](Index begin, Index end) {
      for (Index i = begin; i != end; ++i) grid.node[i].momentum.setZero();
    });
  }

  /// v_p = alpha (v_p + sum phi (v~_I - v_I^t)) + (1 - alpha) sum phi v~_I, then
  /// (mv)_I^{t+dt} += phi m_p v_p (eq. 2.64), scattered with the slab colouring.
  static void update_velocity_and_remap(Body<Dim>& body, StepContext<Dim>& ctx) {
    auto& p = body.particles;
    const auto& g = ctx.grid.geometry;
    Grid<Dim>& grid = kernels::grid_of(body, ctx.grid);
    NodeRecord<Dim>* node = grid.node.data();
    const NodeVelocity<Dim>* vel = grid.velocity.data();
    const Real alpha = ctx.settings.flip_fraction;
    MatU<Dim>* affine = kernels::affine_of(p);
    const keys::PolyModes<Dim>* poly = kernels::polypic_of<Dim, Shape>(p);
    for_each_tile_coloured(body.bins, {HaloArray::of(grid.node)}, [&](const Index* index, Index count) {
      axisym::StencilFor<Dim, Shape, Coords> st;
      const ParticleDomain<Dim, Shape> domain(p);
      for (Index k = 0; k < count; ++k) {
        const Index i = index[k];
        st.compute(p.x[i], g, domain(i));
        Vec<Dim> v_pic = Vec<Dim>::Zero(), dv = Vec<Dim>::Zero();
        for (int a = 0; a < st.count; ++a) {
          const NodeVelocity<Dim>& nv = vel[st.node[a]];
          v_pic += st.w[a] * nv.updated;
          dv += st.w[a] * (nv.updated - nv.mapped);
        }
        if (affine) {
          // APIC: the particle's new state (v_p, C_p) from the trial velocities, re-mapped with eq. 5.37
          // (docs/theory.md §2, velocity transfers). C_p must be the one that goes with v_p: re-mapping v^{t+dt} with
          // the previous step's C_p made the re-mapped velocity, and so L_p and the next C_p, a running average of past
          // velocity gradients (a strain rate delayed by steps), which pumped energy into the acoustic modes until a
          // particle inverted (dam break at 0.093 s; a 1D column at rest at 0.091 s). The final C_p is taken in the
          // last pass from the re-mapped v^{t+dt}, like L_p.
          p.v[i] = v_pic;
          const auto trial = [&](Index n) { return Vec<Dim>(vel[n].updated); };
          const Real light = kernels::apic_light_node_mass<Dim, Coords>(p, i, g);
          const Mat<Dim> C = kernels::affine_matrix_of_trial(st, node, light, v_pic, trial);
          if constexpr (std::is_same_v<Shape, LinearHat>) {
            if (poly) {  // PolyPIC: the higher modes from the same trial velocities
              const keys::PolyModes<Dim> modes = kernels::polypic_modes_of_trial(st, g, node, light, v_pic, trial);
              for (int a = 0; a < st.count; ++a) {
                const Vec<Dim> r = st.node_offset(a);
                node[st.node[a]].momentum +=
                    st.w[a] * p.mass[i] * (v_pic + C * r + kernels::polypic_higher_velocity<Dim>(modes, r));
              }
              continue;
            }
          }
          for (int a = 0; a < st.count; ++a)
            node[st.node[a]].momentum += st.w[a] * p.mass[i] * (v_pic + C * st.node_offset(a));
          continue;
        }
        const Vec<Dim> v = alpha * (p.v[i] + dv) + (1 - alpha) * v_pic;
        p.v[i] = v;
        const Vec<Dim> mv = p.mass[i] * v;
        for (int a = 0; a < st.count; ++a) node[st.node[a]].momentum += st.w[a] * mv;
      }
    });
  }

  /// v_I^{t+dt} = (mv)_I^{t+dt} / m_I (eq. 2.65), stored in `mapped`; the hooks of the re-mapped stage (the face
  /// conditions again, GridBoundary).
  static void remapped_velocity(StepContext<Dim>& ctx) {
    auto& grid = ctx.grid;
    const Real cutoff = ctx.settings.mass_cutoff;
    for_each_node_block(grid.size(), ctx.active_nodes, 1 << 12, [&](Index begin, Index end) {
      for (Index i = begin; i != end; ++i) {
        const NodeRecord<Dim>& n = grid.node[i];
        if (n.mass > cutoff)
          grid.velocity[i].mapped = n.momentum / n.mass;
        else
          grid.velocity[i].mapped.setZero();
      }
    });
    ctx.hooks.grid_velocity(ctx, GridStage::remapped);
  }

  /// x_p += dt sum phi v~_I (Alg. 2); L_p = sum v_I^{t+dt} (x) grad phi at the old positions; F update.
  /// Writes the velocity gradient of particle i to L_out[i - begin].
  static bool update_position_and_deformation(Body<Dim>& body, const StepContext<Dim>& ctx, Index begin, Index end,
                                              MatU<Dim>* L_out) {
    auto& p = body.particles;
    const auto& g = ctx.grid.geometry;
    const Vec<Dim> keep_lower = ctx.boundary.keep_lower(g), keep_upper = ctx.boundary.keep_upper(g);
    const Vec<Dim>& wall_lower = ctx.boundary.wall_lower();
    const Vec<Dim>& wall_upper = ctx.boundary.wall_upper();
    const NodeVelocity<Dim>* vel = kernels::grid_of(body, ctx.grid).velocity.data();
    const Real dt = ctx.dt;
    MatU<Dim>* affine = kernels::affine_of(p);
    keys::PolyModes<Dim>* poly = kernels::polypic_of<Dim, Shape>(p);
    [[maybe_unused]] const axisym::HoopFields hoop =
        Coords::axisymmetric ? axisym::hoop_fields(p) : axisym::HoopFields{};
    axisym::StencilFor<Dim, Shape, Coords> st;
    const ParticleDomain<Dim, Shape> domain(p);
    const bool deforms = body.material->tracks_deformation();  // F stays I otherwise
    bool ok = true;
    for (Index i = begin; i != end; ++i) {
      st.compute(p.x[i], g, domain(i));
      if constexpr (Coords::axisymmetric) {
        hoop.rate[i] = axisym::hoop_rate(st, [&](Index n) { return vel[n].mapped; });
        ok &= axisym::update_hoop_stretch(hoop.stretch[i], hoop.rate[i], dt);
      }
      Vec<Dim> v_move = Vec<Dim>::Zero();
      Mat<Dim> L = Mat<Dim>::Zero();
      for (int a = 0; a < st.count; ++a) {
        const NodeVelocity<Dim>& nv = vel[st.node[a]];
        v_move += st.w[a] * nv.updated;
        for (int c = 0; c < Dim; ++c) L.col(c) += nv.mapped * st.grad[a][c];
      }
      p.x[i] += dt * v_move;
      kernels::keep_inside_walls<Dim>(p.x[i], wall_lower, wall_upper);
      L_out[i - begin] = L;
      if (affine) affine[i] = kernels::affine_matrix(st, [&](Index n) { return Vec<Dim>(vel[n].mapped); });
      if constexpr (std::is_same_v<Shape, LinearHat>)
        if (poly) poly[i] = kernels::polypic_modes(st, g, [&](Index n) { return Vec<Dim>(vel[n].mapped); });
      ok &= (!deforms || kernels::update_deformation_gradient<Dim>(p.F[i], L, dt)) &&
            kernels::inside<Dim, Coords>(p.x[i], keep_lower, keep_upper) && std::isfinite(p.v[i].sum());
    }
    return ok;
  }
};

}  // namespace mpm
