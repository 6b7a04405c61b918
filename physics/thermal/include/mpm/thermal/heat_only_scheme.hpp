#pragma once
/// \file heat_only_scheme.hpp
/// `solver.scheme: heat`, a thermal analysis: heat conduction alone (review Alg. 8) on bodies that stay where they
/// are. The mechanics' CFL bound (eq. 2.73) does not apply, so the step is the diffusion bound h^2 rho c / (2 dim k)
/// of heat_conduction.hpp, 1.8e-2 s for steel on 1 mm cells instead of the 1.4e-7 s its elastic waves allow: a
/// second of conduction takes tens of steps instead of millions. A step bins the particles, maps their mass and
/// momentum (the contact module's after-P2G phase reads them: a pair's finite conductance, TC.1-TC.2) and runs the
/// modules' after-P2G phase, in which the conduction module takes the whole thermal step. No grid velocity, no
/// particle motion, no stress update: positions, F and stresses keep their initial values.

#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/schemes/scheme.hpp"
#include "mpm/schemes/transfer_kernels.hpp"

namespace mpm::thermal {

template <int Dim, class Shape, class Coords = CartesianCoordinates>
class HeatOnlyScheme final : public ShapedScheme<Dim, Shape> {
 public:
  std::string_view name() const override { return "heat"; }
  bool runs_distributed() const override { return true; }
  bool has_mechanics() const override { return false; }

  void advance(StepContext<Dim>& ctx) override {
    {
      PhaseTimer timer(ctx.profile, StepPhase::p2g);
      kernels::bin_bodies<Dim, Shape>(ctx);
      kernels::reset_grid(ctx.grid, ctx.active_nodes);
      kernels::reset_own_grids(ctx.bodies, ctx.active_nodes);
      for (auto& body : ctx.bodies) kernels::particles_to_grid<Dim, Shape, true, false, Coords>(body, ctx.grid);
    }
    PhaseTimer timer(ctx.profile, StepPhase::grid_update);
    ctx.hooks.after_p2g(ctx);
  }
};

}  // namespace mpm::thermal
