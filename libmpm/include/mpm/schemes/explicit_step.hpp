#pragma once
/// \file explicit_step.hpp
/// The parts of a step that USL and MUSL share: the first mapping with the grid update, and the
/// batched stress update.

#include <algorithm>
#include <mutex>

#include "mpm/core/parallel_chunks.hpp"

#include "mpm/particles/field_keys.hpp"
#include "mpm/schemes/transfer_kernels.hpp"

namespace mpm::kernels {

/// Bins particles, maps mass, momentum and force to the grid (P2G), computes v^t and the updated
/// velocity, and runs the module hooks at both stages (the face conditions among them: GridBoundary runs first in
/// each phase, its tractions after P2G and its velocity constraints at each stage).
template <int Dim, class Shape, class Coords = CartesianCoordinates>
void map_and_update_grid(StepContext<Dim>& ctx) {
  {
    PhaseTimer timer(ctx.profile, StepPhase::p2g);
    bin_bodies<Dim, Shape>(ctx);
    reset_grid(ctx.grid, ctx.active_nodes);
    reset_own_grids(ctx.bodies, ctx.active_nodes);
    for (auto& body : ctx.bodies) particles_to_grid<Dim, Shape, true, true, Coords>(body, ctx.grid);
  }
  PhaseTimer timer(ctx.profile, StepPhase::grid_update);
  ctx.hooks.after_p2g(ctx);
  update_grid_velocity(ctx.grid, ctx.settings, ctx.dt, ctx.active_nodes);
  ctx.hooks.grid_velocity(ctx, GridStage::mapped);
  ctx.hooks.grid_velocity(ctx, GridStage::updated);
}

/// Grid-to-particle transfer fused with the constitutive update, block by block:
/// `transfer(body, begin, end, L)` updates the kinematics of a block of particles and writes their
/// velocity gradients to L[0 .. end-begin); the body's material then updates the stress of the same block
/// while it is in cache. L lives in a per-thread block buffer, so it costs no per-particle memory; it is
/// copied to the on-demand particle field "velocity_gradient" only when that field exists (output).
/// When a module must run between the transfer and the stress update (phase_after_g2p), the gradients of
/// all particles are kept in the body's scratch array and the stress update runs after the hooks.
/// With profiling, each block times its two halves (FusedSplit); without, the only cost is one test of a
/// local flag per block of 1024 particles.
template <int Dim, class Transfer>
void transfer_and_update_stress(StepContext<Dim>& ctx, Transfer&& transfer) {
  constexpr Index block = 1024;
  const bool fused = !ctx.hooks.has_after_g2p();
  const bool profiled = ctx.profile != nullptr;
  FusedSplit split;
  const auto start = profiled ? StepProfile::Clock::now() : StepProfile::Clock::time_point{};
  ctx.wave_speed = {};
  // The bound is a maximum (WaveSpeedBound::merge), so merging the chunks' bounds in any order gives the same bits.
  std::mutex merge_mutex;
  auto merge = [&](const WaveSpeedBound<Dim>& b) {
    const std::lock_guard lock(merge_mutex);
    ctx.wave_speed.merge(b);
  };
  for (auto& body : ctx.bodies) {
    auto& p = body.particles;
    auto& material = *body.material;
    MatU<Dim>* stored =
        p.has_field(keys::velocity_gradient<Dim>) ? p.field(keys::velocity_gradient<Dim>).data() : nullptr;
    if (!fused) body.velocity_gradient.resize(p.size());
    parallel_chunks(Index{0}, p.size(), block, [&](Index chunk_begin, Index chunk_end) {
      WaveSpeedBound<Dim> b;
      thread_local std::vector<MatU<Dim>> buffer;
      buffer.resize(block);
      for (Index begin = chunk_begin; begin < chunk_end; begin += block) {
        const Index end = std::min(begin + block, chunk_end);
        MatU<Dim>* L = fused ? buffer.data() : body.velocity_gradient.data() + begin;
        const auto t0 = profiled ? StepProfile::Clock::now() : StepProfile::Clock::time_point{};
        if (!transfer(body, begin, end, L)) ctx.guard_tripped = true;
        if (stored) std::copy(L, L + (end - begin), stored + begin);
        if (!fused) continue;
        if (!profiled) {
          b.merge(material.update_stress(p, begin, end, L, ctx.dt));
          continue;
        }
        const auto t1 = StepProfile::Clock::now();
        b.merge(material.update_stress(p, begin, end, L, ctx.dt));
        split.transfer += std::chrono::duration<double>(t1 - t0).count();
        split.stress += StepProfile::since(t1);
      }
      merge(b);
    });
  }
  if (profiled) {
    if (fused)
      split.distribute(*ctx.profile, StepProfile::since(start));
    else
      ctx.profile->add(StepPhase::g2p, StepProfile::since(start));
  }
  if (!fused) {
    ctx.hooks.after_g2p(ctx);
    PhaseTimer timer(ctx.profile, StepPhase::stress_update);
    for (auto& body : ctx.bodies) {
      auto& p = body.particles;
      parallel_chunks(Index{0}, p.size(), block, [&](Index chunk_begin, Index chunk_end) {
        merge(body.material->update_stress(p, chunk_begin, chunk_end, body.velocity_gradient.data() + chunk_begin,
                                           ctx.dt));
      });
    }
  }
  if (!ctx.wave_speed.finite) ctx.guard_tripped = true;
  ctx.hooks.after_stress(ctx);
}

}  // namespace mpm::kernels
