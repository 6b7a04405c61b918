// The gravity stage (simulation/gravity_stage.hpp; docs/theory.md §20, eqs 20.3-20.4).
#include "mpm/simulation/gravity_stage.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>

#include "mpm/core/exact_sum.hpp"
#include "mpm/parallel/communicator.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/schemes/local_damping.hpp"

namespace mpm {
namespace {

/// Measures the unbalanced force ratio of eq. 20.3 at every step, R = |f_u| / |m g|: the nodal forces
/// f = f_int + f_ext + m g of the components the step left free (not held by a face, a set, contact or the cut-off),
/// over the nodal weights. A component is free when its updated velocity is the damped update of eq. 2.74 of its
/// mapped one; the conditions replace a held one by its prescribed value, whose reaction is no unbalance.
template <int Dim>
class UnbalancedForceMeter final : public Module<Dim> {
 public:
  std::string_view name() const override { return "gravity_stage"; }
  unsigned phases() const override { return phase_grid_velocity; }
  std::string why_not_distributed() const override { return {}; }
  void on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) override {
    if (stage != GridStage::updated) return;
    std::vector<const Grid<Dim>*> fields;  // the shared grid and the bodies' own (contact), each once
    for (const auto& body : ctx.bodies) {
      const Grid<Dim>* grid = body.separate_grid ? body.separate_grid : &ctx.grid;
      if (std::find(fields.begin(), fields.end(), grid) == fields.end()) fields.push_back(grid);
    }
    const Real cutoff = ctx.settings.mass_cutoff, dt = ctx.dt, alpha = ctx.settings.damping;
    const Vec<Dim> g = ctx.settings.gravity;
    std::array<ExactSum, 2> sums;  // |f_u|^2, |m g|^2 over the nodes this rank owns
    for (const Grid<Dim>* grid : fields)
      for_each_node_in_order(grid->size(), ctx.active_nodes, [&](Index I) {
        if (!ctx.owned_nodes.contains(I)) return;
        const NodeRecord<Dim>& n = grid->node[I];
        if (!(n.mass > cutoff)) return;
        const NodeVelocity<Dim>& v = grid->velocity[I];
        const Vec<Dim> f = Vec<Dim>(n.force) + n.mass * g;
        const Vec<Dim> mapped(v.mapped);
        const Vec<Dim> free = kernels::damped_velocity<Dim>(mapped, f, n.mass, dt, alpha);
        for (int c = 0; c < Dim; ++c) {
          // the same arithmetic up to the compiler's contractions: equal to a few roundings of the terms
          const Real scale = std::abs(mapped[c]) + dt * std::abs(f[c]) / n.mass;
          if (std::abs(v.updated[c] - free[c]) <= 1e-9 * scale) sums[0] += f[c] * f[c];
        }
        sums[1] += n.mass * n.mass * g.squaredNorm();
      });
    if (ctx.comm) ctx.comm->sum(std::span<ExactSum>(sums));
    ratio_ = sums[1].value() > 0 ? std::sqrt(sums[0].value() / sums[1].value()) : 0;
  }
  Real ratio() const { return ratio_; }

 private:
  Real ratio_ = 0;
};

template <int Dim>
Real kinetic_energy(const Simulation<Dim>& sim) {
  Real e = 0;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i)
      e += 0.5 * b.particles.mass[i] * Vec<Dim>(b.particles.v[i]).squaredNorm();
  return e;
}

/// Each body's particle positions by id (ids are stable under the sorts of the stage).
template <int Dim>
std::vector<std::vector<VecU<Dim>>> positions_by_id(const Simulation<Dim>& sim) {
  std::vector<std::vector<VecU<Dim>>> out;
  for (const auto& b : sim.bodies()) {
    const auto& p = b.particles;
    std::vector<VecU<Dim>> x;
    for (Index i = 0; i < p.size(); ++i) {
      const std::size_t id = p.id[static_cast<std::size_t>(i)];
      if (x.size() <= id) x.resize(id + 1);
      x[id] = p.x[i];
    }
    out.push_back(std::move(x));
  }
  return out;
}

/// m: the largest distance from `start` (positions_by_id) of a particle now.
template <int Dim>
Real largest_displacement(const Simulation<Dim>& sim, const std::vector<std::vector<VecU<Dim>>>& start) {
  Real d = 0;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    const auto& p = sim.bodies()[b].particles;
    for (Index i = 0; i < p.size(); ++i)
      d = std::max(d, Real((p.x[i] - start[b][p.id[static_cast<std::size_t>(i)]]).norm()));
  }
  return d;
}

/// The end of the stage: every particle at rest, the displacement counted from here (eq. 20.4).
template <int Dim>
void come_to_rest(Simulation<Dim>& sim) {
  const bool moves_reference = sim.scheme().reorders_particles();  // TLMPM keeps its reference configuration
  for (auto& b : sim.bodies()) {
    auto& p = b.particles;
    for (auto& v : p.v) v.setZero();
    if (p.has_field(keys::affine_velocity<Dim>))
      for (auto& c : p.field(keys::affine_velocity<Dim>)) c.setZero();
    if (p.has_field(keys::polypic_modes<Dim>))
      for (auto& m : p.field(keys::polypic_modes<Dim>)) m = keys::zero_poly_modes<Dim>();
    if (p.has_field(keys::velocity_gradient<Dim>))
      for (auto& l : p.field(keys::velocity_gradient<Dim>)) l.setZero();
    if (p.has_field(keys::hoop_velocity_gradient))
      for (auto& l : p.field(keys::hoop_velocity_gradient)) l = 0;
    if (moves_reference && p.has_field(keys::reference_position<Dim>))
      std::copy(p.x.begin(), p.x.end(), p.field(keys::reference_position<Dim>).begin());
  }
  sim.particles_changed();
}

}  // namespace

std::string GravityStageReport::summary() const {
  if (converged)
    return fmt::format(
        "gravity stage: at rest after {} steps (unbalanced force ratio {:.3g} < {:.3g} for {} steps; largest "
        "displacement {:.3g} m)",
        steps, ratio, tolerance, settled_steps, largest_displacement);
  return fmt::format(
      "gravity stage: not at rest after {} steps (unbalanced force ratio {:.3g}, tolerance {:.3g}; largest "
      "displacement {:.3g} m)",
      steps, ratio, tolerance, largest_displacement);
}

template <int Dim>
GravityStageReport run_gravity_stage(Simulation<Dim>& sim, const GravityStageSettings& stage) {
  const auto meter = std::make_shared<UnbalancedForceMeter<Dim>>();
  sim.add_module(meter);  // last: it sees the velocities every condition and contact have set
  // The stage's transfers: its damping, and PIC (flip_fraction 0; APIC and PolyPIC are PIC already). A held
  // velocity that depends on t takes its value of t = -dt at a step's start and of 0 at its end: under FLIP the
  // particles at held nodes would add that difference to their velocity at every step, as if the clock ran, and
  // carry it to the nodes around them (a footing held at -0.5 t would never let the stage settle). PIC also damps
  // the grid-scale modes FLIP keeps, and the settled state is the same static one.
  const TransferSettings<Dim> scene_transfer = sim.settings().transfer;
  TransferSettings<Dim> transfer = scene_transfer;
  transfer.damping = stage.damping;
  transfer.flip_fraction = 0;
  sim.set_transfer_settings(transfer);
  GravityStageReport report;
  report.tolerance = stage.tolerance;
  const auto start = positions_by_id(sim);
  Index below = 0;
  while (report.steps < stage.max_steps) {
    // each step runs from -dt to 0: the conditions' values at its end (the held velocities the positions move with)
    // are those of t = 0, and the clock stays there
    const Real dt = sim.time_step_toward(sim.settings().end_time);
    sim.set_time(-dt);
    sim.advance(dt);
    ++report.steps;
    report.ratio = meter->ratio();
    report.rows.push_back({report.steps, dt, report.ratio, kinetic_energy(sim)});
    below = report.ratio < stage.tolerance ? below + 1 : 0;
    if (below >= settled_steps) {
      report.converged = true;
      break;
    }
  }
  report.largest_displacement = largest_displacement(sim, start);
  sim.remove_module(meter.get());
  sim.set_transfer_settings(scene_transfer);
  come_to_rest(sim);
  sim.reset_clock();
  return report;
}

template GravityStageReport run_gravity_stage<1>(Simulation<1>&, const GravityStageSettings&);
template GravityStageReport run_gravity_stage<2>(Simulation<2>&, const GravityStageSettings&);
template GravityStageReport run_gravity_stage<3>(Simulation<3>&, const GravityStageSettings&);

}  // namespace mpm
