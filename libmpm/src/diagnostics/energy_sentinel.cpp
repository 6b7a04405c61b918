// The energy sentinel (energy_sentinel.hpp; docs/theory.md §8): the balance E(t) - E(0) - W(t) + E_out(t) every
// `interval` steps, the work W accumulated every step, E_out the energy that left through outflow faces.
#include "mpm/diagnostics/energy_sentinel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/simulation/energy_audit.hpp"

namespace mpm {

std::string EnergyDrift::message() const {
  return fmt::format(
      "energy sentinel: at step {} (t = {:.9g} s) the energy balance E(t) - E(0) - W = {:+.6g} J exceeds the "
      "tolerance {:.6g} J; {} grew most. Hint: {} (measured: {})",
      step, time, balance, tolerance, grown, hint ? hint->hint : "", hint ? hint->measurement : "");
}

template <int Dim>
EnergySentinel<Dim>::EnergySentinel(Real fraction, EnergyDriftAction action, HintContext context,
                                    const EnergyBalance& initial, bool boundary_work, std::vector<Partner> partners,
                                    int interval)
    : fraction_(fraction),
      action_(action),
      context_(std::move(context)),
      initial_(initial),
      boundary_work_(boundary_work),
      partners_(std::move(partners)),
      interval_(std::max(1, interval)),
      scale_(initial.kinetic + initial.strain + initial.plastic_work) {}

namespace {

/// sum over the bodies of m_p b_p . v_p, or 0 when no body carries the field "body_force".
template <int Dim>
Real body_force_power(const std::vector<Body<Dim>>& bodies, Communicator* comm) {
  // Whether a body has the field is the same on every rank (the layout is the scene's): without one, no reduction.
  if (std::none_of(bodies.begin(), bodies.end(),
                   [](const Body<Dim>& b) { return b.particles.has_field(keys::body_force<Dim>); }))
    return 0;
  ExactSum power;
  for (const auto& b : bodies) {
    const auto& p = b.particles;
    if (!p.has_field(keys::body_force<Dim>)) continue;
    const auto& force = p.field(keys::body_force<Dim>);
    for (Index i = 0; i < p.size(); ++i) power += p.mass[i] * Vec<Dim>(force[i]).dot(Vec<Dim>(p.v[i]));
  }
  if (comm) comm->sum(std::span<ExactSum>(&power, 1));  // a distributed run: every rank's particles
  return power.value();
}

}  // namespace

// The terms of EnergyBalance::total() exactly as Simulation::energy() sums them (energy_audit.hpp): kinetic and
// gravity potential per particle, the materials' strain and dissipated energy, the modules' shares.
template <int Dim>
EnergyBalance EnergySentinel<Dim>::audit(const StepContext<Dim>& ctx) const {
  EnergySums sums;
  for (const auto& b : ctx.bodies) add_body_energy(b, ctx.settings.gravity, ctx.hooks.all(), sums);
  if (ctx.comm) sums.reduce(*ctx.comm);
  return sums.value();
}

template <int Dim>
void EnergySentinel<Dim>::before_step(StepContext<Dim>& ctx) {
  body_force_start_ = 0.5 * ctx.dt * body_force_power(ctx.bodies, ctx.comm);
}

template <int Dim>
void EnergySentinel<Dim>::on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) {
  if (stage != GridStage::updated) return;  // the nodal forces of the step are final here in every scheme
  if (!ctx.boundary.does_work()) return;    // held faces at rest, no traction: zero on every rank, no reduction
  ExactSum work = ctx.boundary.work(ctx.grid.node, ctx.grid.velocity, ctx.settings.gravity, ctx.settings.mass_cutoff,
                                    ctx.time, ctx.dt, ctx.owned_nodes, ctx.active_nodes);
  if (ctx.comm) ctx.comm->sum(std::span<ExactSum>(&work, 1));  // each rank summed the nodes it owns
  work_ += work.value();
}

template <int Dim>
void EnergySentinel<Dim>::end_of_step(StepContext<Dim>& ctx) {
  // The rigid partners' work of the step: F . V dt. A plane's velocity at the middle of the step; a rigid body's
  // at its end, the velocity the contact module has just given its particles (asked of the module, not read from
  // a particle: in a distributed run a rank may hold none of them). The force is the same on every rank.
  for (const auto& partner : partners_) {
    if (const auto w = partner.provider->last_work(partner.index)) {  // a held particle set: its own sum
      work_ += *w;
      continue;
    }
    const Vec<Dim> force = partner.provider->last_reaction(partner.index).force;
    const Real t = partner.body >= 0 ? ctx.time + ctx.dt : ctx.time + 0.5 * ctx.dt;
    work_ += force.dot(partner.provider->partner_velocity(partner.index, t)) * ctx.dt;
  }
  work_ += body_force_start_ + 0.5 * ctx.dt * body_force_power(ctx.bodies, ctx.comm);
  if (ctx.step % interval_ != 0) return;
  const EnergyBalance e = audit(ctx);
  Real balance = (e.total() - initial_.total()) - work_;
  // What left through outflow faces took its energy along (GridBoundary's books, the same on every rank).
  if (ctx.boundary.removes_particles()) balance += ctx.boundary.outflow_energy();
  // What eroded took its energy along too (the failure module's books, the same on every rank).
  for (const auto& m : ctx.hooks.all()) balance += m->removed_energy();
  const Real scale = e.kinetic + e.strain + e.plastic_work + std::abs(e.gravity - initial_.gravity) + std::abs(work_);
  if (scale > scale_ || std::isnan(scale)) scale_ = scale;
  // The scale never falls below the round-off of the energies themselves, 1e-9 of the terms of E(0): a body at rest
  // that stores no energy (incompressible water) has a scale of round-off, and the 1e-12 E(0) its pressure solve
  // leaves in the gravity potential read as a drift 20x the tolerance.
  const Real round_off =
      1e-9 * (std::abs(initial_.gravity) + initial_.kinetic + initial_.strain + initial_.plastic_work);
  const Real tolerance = fraction_ * std::max(scale_, round_off);
  last_ratio_ = tolerance > 0 ? balance / tolerance : 0;
  if (last_ratio_ > largest_ratio_) {
    largest_ratio_ = last_ratio_;
    largest_ratio_step_ = ctx.step;
  }
  if (drift_ || !(last_ratio_ > 1)) return;
  EnergyDrift d;
  d.step = ctx.step;
  d.time = ctx.time + ctx.dt;
  d.balance = balance;
  d.tolerance = tolerance;
  const std::array<std::pair<const char*, Real>, 4> changes{{{"kinetic energy", e.kinetic - initial_.kinetic},
                                                             {"strain energy", e.strain - initial_.strain},
                                                             {"gravity potential", e.gravity - initial_.gravity},
                                                             {"plastic work", e.plastic_work - initial_.plastic_work}}};
  std::size_t most = 0;
  for (std::size_t k = 1; k < changes.size(); ++k)
    if (changes[k].second > changes[most].second) most = k;
  d.grown = fmt::format(
      "{} ({:+.4g} J; kinetic {:+.4g} J, strain {:+.4g} J, gravity potential {:+.4g} J, plastic "
      "work {:+.4g} J, external work {:+.4g} J since t = 0)",
      changes[most].first, changes[most].second, changes[0].second, changes[1].second, changes[2].second,
      changes[3].second, work_);
  d.hint = &find_energy_hint(context_, trigger_energy);
  drift_ = std::move(d);
}

template <int Dim>
void EnergySentinel<Dim>::save_state(StateArchive& archive, const std::string& prefix) const {
  archive.put_number(prefix + "work", work_);
  archive.put_number(prefix + "scale", scale_);
  archive.put_number(prefix + "largest_ratio", largest_ratio_);
  archive.put_integer(prefix + "largest_ratio_step", largest_ratio_step_);
  archive.put_integer(prefix + "drift_step", drift_ ? drift_->step : 0);
  // E(0): the scene's initial state, or the state a gravity stage settled to, which a restart does not settle again
  archive.put_number(prefix + "initial_kinetic", initial_.kinetic);
  archive.put_number(prefix + "initial_strain", initial_.strain);
  archive.put_number(prefix + "initial_gravity", initial_.gravity);
  archive.put_number(prefix + "initial_plastic_work", initial_.plastic_work);
}

template <int Dim>
void EnergySentinel<Dim>::restore_state(const StateArchive& archive, const std::string& prefix) {
  // A checkpoint written before the sentinel existed continues with W = 0 from the restart (E(0) is the
  // scene's initial state either way); one written before E(0) was kept has the scene's initial state, which a
  // scene without a gravity stage rebuilds.
  if (!archive.contains(prefix + "work")) return;
  if (archive.contains(prefix + "initial_kinetic")) {
    initial_.kinetic = archive.number(prefix + "initial_kinetic");
    initial_.strain = archive.number(prefix + "initial_strain");
    initial_.gravity = archive.number(prefix + "initial_gravity");
    initial_.plastic_work = archive.number(prefix + "initial_plastic_work");
  }
  work_ = archive.number(prefix + "work");
  scale_ = archive.number(prefix + "scale");
  largest_ratio_ = archive.number(prefix + "largest_ratio");
  largest_ratio_step_ = archive.integer(prefix + "largest_ratio_step");
  // A drift found before the saved state stays found (the run loop warned then: it warns on the step of the
  // drift only); one after it is forgotten and found again if the balance exceeds the tolerance again.
  if (const Index step = archive.integer(prefix + "drift_step"); step == 0) {
    drift_.reset();
  } else if (!drift_ || drift_->step != step) {
    drift_ = EnergyDrift{};
    drift_->step = step;
  }
}

template class EnergySentinel<1>;
template class EnergySentinel<2>;
template class EnergySentinel<3>;

}  // namespace mpm
