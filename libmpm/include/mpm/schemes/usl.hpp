#pragma once
/// \file usl.hpp
/// Update Stress Last (review §2.5.3, Algorithm 1) with the PIC/FLIP blend (eq. 2.53), APIC or PolyPIC, and the
/// small-mass cut-off (eq. 2.63): one mapping to the grid, one transfer back. Axisymmetric (Coords): the hoop
/// rate L_tt = sum T_I v_rI^{t+dt} and stretch F_tt with the in-plane L and F (axisymmetric.hpp).

#include "mpm/schemes/explicit_step.hpp"
#include "mpm/schemes/scheme.hpp"

namespace mpm {

template <int Dim, class Shape, class Coords = CartesianCoordinates>
class Usl final : public ShapedScheme<Dim, Shape> {
 public:
  std::string_view name() const override { return "usl"; }
  bool runs_distributed() const override { return true; }

  void advance(StepContext<Dim>& ctx) override {
    kernels::map_and_update_grid<Dim, Shape, Coords>(ctx);
    kernels::transfer_and_update_stress(ctx, [&](Body<Dim>& body, Index begin, Index end, MatU<Dim>* L) {
      return grid_to_particles(body, ctx, begin, end, L);
    });
  }

 private:
  /// G2P: v_p = alpha (v_p + sum phi (v_I^{t+dt} - v_I^t)) + (1 - alpha) sum phi v_I^{t+dt};
  /// x_p += dt sum phi v_I^{t+dt}; L_p = sum v_I^{t+dt} (x) grad phi (old positions); F update.
  /// Writes the velocity gradient of particle i to L_out[i - begin].
  static bool grid_to_particles(Body<Dim>& body, const StepContext<Dim>& ctx, Index begin, Index end,
                                MatU<Dim>* L_out) {
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
    [[maybe_unused]] const axisym::HoopFields hoop =
        Coords::axisymmetric ? axisym::hoop_fields(p) : axisym::HoopFields{};
    axisym::StencilFor<Dim, Shape, Coords> st;
    const ParticleDomain<Dim, Shape> domain(p);
    const bool deforms = body.material->tracks_deformation();  // F stays I otherwise
    bool ok = true;
    for (Index i = begin; i != end; ++i) {
      st.compute(p.x[i], g, domain(i));
      if constexpr (Coords::axisymmetric) {
        hoop.rate[i] = axisym::hoop_rate(st, [&](Index n) { return vel[n].updated; });
        ok &= axisym::update_hoop_stretch(hoop.stretch[i], hoop.rate[i], dt);
      }
      Vec<Dim> v_pic = Vec<Dim>::Zero(), dv = Vec<Dim>::Zero();
      Mat<Dim> L = Mat<Dim>::Zero();
      for (int a = 0; a < st.count; ++a) {
        const NodeVelocity<Dim>& nv = vel[st.node[a]];
        const Real w = st.w[a];
        v_pic += w * nv.updated;
        dv += w * (nv.updated - nv.mapped);
        for (int c = 0; c < Dim; ++c) L.col(c) += nv.updated * st.grad[a][c];
      }
      if (affine) {  // APIC: PIC velocity plus the affine matrix (PolyPIC: and the higher modes)
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
      L_out[i - begin] = L;
      ok &= (!deforms || kernels::update_deformation_gradient<Dim>(p.F[i], L, dt)) &&
            kernels::inside<Dim, Coords>(p.x[i], keep_lower, keep_upper) && std::isfinite(p.v[i].sum());
    }
    return ok;
  }
};

}  // namespace mpm
