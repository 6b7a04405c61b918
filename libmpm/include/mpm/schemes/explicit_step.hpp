#pragma once
/// \file explicit_step.hpp
/// The parts of a step that USL and MUSL share: the first mapping with the grid update, and the
/// batched stress update.

#include "mpm/schemes/transfer_kernels.hpp"

namespace mpm::kernels {

/// Bins particles, maps mass, momentum and force to the grid (P2G), computes v^t and the updated
/// velocity, and applies boundary conditions and module hooks at both stages.
template <int Dim, class Shape>
void map_and_update_grid(StepContext<Dim>& ctx) {
  const auto& g = ctx.grid.geometry;
  for (auto& body : ctx.bodies) {
    bin_by_slab(body.particles, g, Shape::slab_cells, body.bins);
    if (body.bins.outside >= 0) ctx.guard_tripped = true;
  }
  reset_grid(ctx.grid);
  for (auto& body : ctx.bodies) particles_to_grid<Dim, Shape>(body, ctx.grid);
  ctx.hooks.after_p2g(ctx);
  update_grid_velocity(ctx.grid, ctx.settings, ctx.dt);
  if (!ctx.boundary.empty()) {
    ctx.boundary.apply(ctx.grid.velocity, &NodeVelocity<Dim>::mapped, ctx.time);
    ctx.boundary.apply(ctx.grid.velocity, &NodeVelocity<Dim>::updated, ctx.time + ctx.dt);
  }
  ctx.hooks.grid_velocity(ctx, GridStage::mapped);
  ctx.hooks.grid_velocity(ctx, GridStage::updated);
}

/// Batched constitutive update of every body (one virtual call per body), gathering the CFL bound.
template <int Dim>
void update_stress(StepContext<Dim>& ctx) {
  ctx.wave_speed = {};
  for (auto& body : ctx.bodies) {
    const auto bound = body.material->update_stress(body.particles, 0, body.particles.size(), ctx.dt);
    ctx.wave_speed.merge(bound);
  }
  if (!ctx.wave_speed.finite) ctx.guard_tripped = true;
  ctx.hooks.after_stress(ctx);
}

}  // namespace mpm::kernels
