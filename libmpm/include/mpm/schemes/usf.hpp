#pragma once
/// \file usf.hpp
/// Update Stress First (Bardenhagen 2002; review Remark 17, the single-body form of Alg. 6, digest
/// §A.3): the velocity gradient and stress are updated from the mapped velocity v^t before the
/// internal force is computed, then the momentum is updated and the particles move:
///   P2G m_I, (mv)_I -> v_I^t;  L_p = sum v_I^t (x) grad phi;  F, sigma updated;
///   f_I = -sum V_p sigma_p grad phi + m_I g;  v_I^{t+dt} = v_I^t + dt f_I/m_I;
///   v_p = alpha (v_p + sum phi (v^{t+dt} - v^t)) + (1 - alpha) sum phi v^{t+dt};  x_p += dt sum phi v^{t+dt}.
/// Axisymmetric (Coords): L_tt = sum T_I v_rI^t and F_tt with L and F (axisymmetric.hpp).

#include "mpm/schemes/explicit_step.hpp"
#include "mpm/schemes/scheme.hpp"

namespace mpm {

template <int Dim, class Shape, class Coords = CartesianCoordinates>
class Usf final : public ShapedScheme<Dim, Shape> {
 public:
  std::string_view name() const override { return "usf"; }
  bool runs_distributed() const override { return true; }

  void advance(StepContext<Dim>& ctx) override {
    auto& grid = ctx.grid;
    {
      PhaseTimer timer(ctx.profile, StepPhase::p2g);
      kernels::bin_bodies<Dim, Shape>(ctx);
      kernels::reset_grid(grid, ctx.active_nodes);
      kernels::reset_own_grids(ctx.bodies, ctx.active_nodes);
      for (auto& body : ctx.bodies) kernels::particles_to_grid<Dim, Shape, true, false, Coords>(body, grid);
    }
    {
      PhaseTimer timer(ctx.profile, StepPhase::grid_update);
      kernels::update_grid_velocity(grid, ctx.settings, ctx.dt, ctx.active_nodes);  // mapped = v^t (force still 0)
      ctx.hooks.grid_velocity(ctx, GridStage::mapped);
    }

    kernels::transfer_and_update_stress(
        ctx, [&](Body<Dim>& body, Index begin, Index end, MatU<Dim>* L) { return deform(body, ctx, begin, end, L); });

    {
      PhaseTimer timer(ctx.profile, StepPhase::p2g);
      for (auto& body : ctx.bodies) kernels::particles_to_grid<Dim, Shape, false, true, Coords>(body, grid);
    }
    {
      PhaseTimer timer(ctx.profile, StepPhase::grid_update);
      ctx.hooks.after_p2g(ctx);  // the face tractions first (GridBoundary)
      momentum_update(ctx);
      ctx.hooks.grid_velocity(ctx, GridStage::updated);
    }
    PhaseTimer timer(ctx.profile, StepPhase::g2p);
    for (auto& body : ctx.bodies) move(body, ctx);
  }

 private:
  /// L_p = sum v_I^t (x) grad phi_I(x_p^t) and F^{t+dt} = (I + dt L_p) F^t.
  static bool deform(Body<Dim>& body, const StepContext<Dim>& ctx, Index begin, Index end, MatU<Dim>* L_out) {
    auto& p = body.particles;
    const auto& g = ctx.grid.geometry;
    const NodeVelocity<Dim>* vel = kernels::grid_of(body, ctx.grid).velocity.data();
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
        ok &= axisym::update_hoop_stretch(hoop.stretch[i], hoop.rate[i], ctx.dt);
      }
      Mat<Dim> L = Mat<Dim>::Zero();
      for (int a = 0; a < st.count; ++a)
        for (int c = 0; c < Dim; ++c) L.col(c) += vel[st.node[a]].mapped * st.grad[a][c];
      L_out[i - begin] = L;
      if (deforms) ok &= kernels::update_deformation_gradient<Dim>(p.F[i], L, ctx.dt);
    }
    return ok;
  }

  /// updated = mapped + dt (f/m + g), with the small-mass cut-off and the local damping (eq. 2.74).
  static void momentum_update(StepContext<Dim>& ctx) {
    auto& grid = ctx.grid;
    for_each_node_block(grid.size(), ctx.active_nodes, 1 << 12, [&](Index begin, Index end) {
      for (Index i = begin; i != end; ++i) {
        const NodeRecord<Dim>& n = grid.node[i];
        NodeVelocity<Dim>& v = grid.velocity[i];
        if (!(n.mass > ctx.settings.mass_cutoff))
          v.updated.setZero();
        else if (ctx.settings.damping > 0)  // eq. 2.74
          v.updated = kernels::damped_velocity<Dim>(v.mapped, n.force + n.mass * ctx.settings.gravity, n.mass, ctx.dt,
                                                    ctx.settings.damping);
        else
          v.updated = v.mapped + ctx.dt * (n.force / n.mass + ctx.settings.gravity);
      }
    });
  }

  /// Particle velocity (PIC/FLIP blend, eq. 2.53) and position (eq. 2.54).
  static void move(Body<Dim>& body, StepContext<Dim>& ctx) {
    auto& p = body.particles;
    const auto& g = ctx.grid.geometry;
    const Vec<Dim> keep_lower = ctx.boundary.keep_lower(g), keep_upper = ctx.boundary.keep_upper(g);
    const Vec<Dim>& wall_lower = ctx.boundary.wall_lower();
    const Vec<Dim>& wall_upper = ctx.boundary.wall_upper();
    const NodeVelocity<Dim>* vel = kernels::grid_of(body, ctx.grid).velocity.data();
    const NodeRecord<Dim>* node = kernels::grid_of(body, ctx.grid).node.data();
    const Real alpha = ctx.settings.flip_fraction, dt = ctx.dt;
    MatU<Dim>* affine = kernels::affine_of(p);
    keys::PolyModes<Dim>* poly = kernels::polypic_of<Dim, Shape>(p);
    parallel_chunks(Index{0}, p.size(), 1024, [&](Index chunk_begin, Index chunk_end) {
      axisym::StencilFor<Dim, Shape, Coords> st;
      const ParticleDomain<Dim, Shape> domain(p);
      bool ok = true;
      for (Index i = chunk_begin; i != chunk_end; ++i) {
        st.compute(p.x[i], g, domain(i));
        Vec<Dim> v_pic = Vec<Dim>::Zero(), dv = Vec<Dim>::Zero();
        for (int a = 0; a < st.count; ++a) {
          const NodeVelocity<Dim>& nv = vel[st.node[a]];
          v_pic += st.w[a] * nv.updated;
          dv += st.w[a] * (nv.updated - nv.mapped);
        }
        if (affine) {  // APIC (PolyPIC: and the higher modes)
          p.v[i] = v_pic;
          const auto trial = [&](Index n) { return Vec<Dim>(vel[n].updated); };
          const Real light = kernels::apic_light_node_mass<Dim, Coords>(p, i, g);
          affine[i] = kernels::affine_matrix_of_trial(st, node, light, v_pic, trial);
          if constexpr (std::is_same_v<Shape, LinearHat>)
            if (poly) poly[i] = kernels::polypic_modes_of_trial(st, g, node, light, v_pic, trial);
        } else {
          p.v[i] = alpha * (p.v[i] + dv) + (1 - alpha) * v_pic;
        }
        p.x[i] += dt * v_pic;
        kernels::keep_inside_walls<Dim>(p.x[i], wall_lower, wall_upper);
        ok &= kernels::inside<Dim, Coords>(p.x[i], keep_lower, keep_upper) && std::isfinite(p.v[i].sum());
      }
      if (!ok) ctx.guard_tripped = true;
    });
  }
};

}  // namespace mpm
