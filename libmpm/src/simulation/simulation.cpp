#include "mpm/simulation/simulation.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "mpm/boundary/face_names.hpp"
#include "mpm/schemes/axisymmetric.hpp"
#include "mpm/simulation/energy_audit.hpp"

namespace mpm {

StabilityError::StabilityError(const StabilityReport& r)
    : std::runtime_error(
          r.field == "energy_balance"
              ? r.detail
              : fmt::format("stability guard: step {} (t = {:.9g} s), body '{}', particle {}, field '{}': {}", r.step,
                            r.time, r.body, r.particle, r.field, r.detail)),
      report_(r) {}

template <int Dim>
Simulation<Dim>::Simulation(const GridGeometry<Dim>& geometry, std::vector<Body<Dim>> bodies,
                            std::unique_ptr<Scheme<Dim>> scheme, GridBoundary<Dim> boundary,
                            const SimulationSettings<Dim>& settings)
    : grid_(geometry),
      bodies_(std::move(bodies)),
      scheme_(std::move(scheme)),
      boundary_(std::make_shared<GridBoundary<Dim>>(std::move(boundary))),
      settings_(settings) {
  if (!boundary_->empty()) hooks_.add(boundary_);  // first: the face conditions hold before any module reads the grid
  scheme_->initialize(bodies_, grid_);
  for (auto& b : bodies_) kinematic_viscosity_ = std::max(kinematic_viscosity_, b.material->kinematic_viscosity());
  particles_changed();
}

template <int Dim>
void Simulation<Dim>::particles_changed() {
  near_cut_known_ = false;
  wave_speed_ = WaveSpeedBound<Dim>{};
  if (scheme_->has_mechanics())
    for (auto& b : bodies_) wave_speed_.merge(b.material->wave_speed_bound(b.particles));
  if (comm_) reduce_wave_speed(wave_speed_, *comm_);
  take_snapshot();
}

template <int Dim>
Index Simulation<Dim>::particle_count() const {
  Index n = 0;
  for (const auto& b : bodies_) n += b.particles.size();
  return n;
}

template <int Dim>
Real Simulation<Dim>::stable_time_step() const {
  Real dt = std::numeric_limits<Real>::infinity();
  const auto& h = grid_.geometry.h;
  for (int d = 0; d < Dim; ++d)
    if (wave_speed_.max_speed[d] > 0) dt = std::min(dt, h[d] / wave_speed_.max_speed[d]);  // eq. 2.73
  if (kinematic_viscosity_ > 0 && scheme_->has_mechanics()) {  // explicit viscous diffusion: dt <= h^2 / (2 Dim nu)
    const Real h_min = h.minCoeff();
    dt = std::min(dt, h_min * h_min / (2 * Dim * kinematic_viscosity_));
  }
  for (const auto& m : hooks_.all()) dt = std::min(dt, m->stable_time_step(bodies_));
  return dt;
}

template <int Dim>
std::string Simulation<Dim>::time_step_limiter() const {
  Real dt = std::numeric_limits<Real>::infinity();
  std::string limiter = "CFL bound h / (c + |v|), eq. 2.73";
  const auto& h = grid_.geometry.h;
  for (int d = 0; d < Dim; ++d)
    if (wave_speed_.max_speed[d] > 0) dt = std::min(dt, h[d] / wave_speed_.max_speed[d]);
  if (kinematic_viscosity_ > 0 && scheme_->has_mechanics())
    if (const Real h_min = h.minCoeff(), bound = h_min * h_min / (2 * Dim * kinematic_viscosity_); bound < dt) {
      dt = bound;
      limiter = "viscous diffusion h^2 / (2 dim nu)";
    }
  for (const auto& m : hooks_.all())
    if (const Real bound = m->stable_time_step(bodies_); bound < dt) {
      dt = bound;
      limiter = std::string(m->time_step_bound());
    }
  return limiter;
}

template <int Dim>
Real Simulation<Dim>::next_time_step() const {
  if (settings_.fixed_dt) return *settings_.fixed_dt;
  return settings_.cfl * stable_time_step();
}

template <int Dim>
bool Simulation<Dim>::finished() const {
  return reached(settings_.end_time);
}

template <int Dim>
bool Simulation<Dim>::reached(Real target_time) const {
  // A step that lands within a millionth of a step of the target counts as the last one.
  return time_ >= target_time - 1e-6 * next_time_step();
}

template <int Dim>
Real Simulation<Dim>::time_step_toward(Real target_time) const {
  return std::min(next_time_step(), target_time - time_ + 1e-12 * target_time);
}

template <int Dim>
void Simulation<Dim>::take_step(Real dt, bool guard) {
  if (scheme_->reorders_particles() && settings_.sort_interval > 0 && step_ % settings_.sort_interval == 0) {
    PhaseTimer timer(profiling_ ? &profile_ : nullptr, StepPhase::sort);
    for (auto& b : bodies_) {
      if (b.particles.size() == 0) continue;  // a body held by other ranks
      b.particles.gather(order_by_cell(b.particles, grid_.geometry, scheme_->slab_cells(), sort_buffers_));
      if (comm_) {  // the keys the sort computed, already in the new order (one pass over the particles fewer)
        const auto& keys = sort_buffers_.sorted;
        std::copy(keys.begin(), keys.end(), b.particles.template field<std::uint64_t>(scatter_key_field).begin());
      }
    }
  }
  StepContext<Dim> ctx{grid_, bodies_, settings_.transfer, *boundary_, hooks_};
  attach(ctx);
  ctx.time = time_;
  ctx.dt = dt;
  ctx.step = step_ + 1;
  ctx.profile = profiling_ ? &profile_ : nullptr;
  if (halo_) {
    const bool always = settings_.exchange_every_scatter;
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      bodies_[b].bins.exchange = always || !near_cut_known_ || near_cut_[b] != 0;
  }
  hooks_.before_step(ctx);
  scheme_->advance(ctx);
  hooks_.end_of_step(ctx);
  bool tripped = ctx.guard_tripped.load();
  unsigned flags = step_flags_fn_ ? step_flags_fn_(step_ + 1, time_ + dt) : 0u;
  bool migrating = false;
  if (comm_) {  // the roll-back is collective: every rank replays the same steps
    // The step's one reduction (a max): the wave-speed bound (as reduce_wave_speed), the guard's flag, whether any
    // particle must migrate (no rank has a leaver on most steps: then no all-to-all either), and the caller's flags
    // (set_step_flags), each flag a max of 0 and 1, and per body whether the next step's scatters exchange ghost
    // nodes (TileBins::exchange).
    constexpr std::size_t first_body = Dim + 3 + step_flag_bits;
    std::vector<double> v(first_body + bodies_.size(), 0.0);
    for (int d = 0; d < Dim; ++d) v[d] = ctx.wave_speed.max_speed[d];
    v[Dim] = ctx.wave_speed.finite ? 0 : 1;
    v[Dim + 1] = tripped ? 1 : 0;
    const bool leaving = scan_particles(std::span<double>(v).subspan(first_body));
    v[Dim + 2] = !tripped && leaving ? 1 : 0;
    for (int b = 0; b < step_flag_bits; ++b) v[Dim + 3 + b] = (flags >> b) & 1u;
    comm_->max(v);
    near_cut_.resize(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b) near_cut_[b] = v[first_body + b] != 0 ? 1 : 0;
    near_cut_known_ = true;
    for (int d = 0; d < Dim; ++d) ctx.wave_speed.max_speed[d] = v[d];
    ctx.wave_speed.finite = v[Dim] == 0;
    tripped = v[Dim + 1] != 0;
    migrating = v[Dim + 2] != 0;
    flags = 0;
    for (int b = 0; b < step_flag_bits; ++b)
      if (v[Dim + 3 + b] != 0) flags |= 1u << b;
  }
  step_flags_ = flags;
  if (guard && tripped) {
    failure_ = std::make_unique<Snapshot>(snapshot_);  // for the flight recorder (replay_failure)
    failure_->dts_since.push_back(dt);
    StabilityReport report = diagnose(dt);
    if (comm_) share_report(report);
    report.step = step_ + 1;
    report.time = time_;
    roll_back_to_previous_step();
    throw StabilityError(report);
  }
  wave_speed_ = ctx.wave_speed;
  time_ += dt;
  ++step_;
  if (comm_) {
    // TLMPM's particles belong to the rank of their reference position: they never migrate, its balance never
    // decays.
    if (scheme_->reorders_particles()) {
      if (migrating) {
        PhaseTimer timer(ctx.profile, StepPhase::migrate);
        migrate();
      }
      if (settings_.rebalance_interval > 0 && step_ % settings_.rebalance_interval == 0) {
        PhaseTimer timer(ctx.profile, StepPhase::rebalance);
        rebalance();
      }
    }
  }
}

template <int Dim>
void Simulation<Dim>::advance(Real dt) {
  if (!(dt > 0) || !std::isfinite(dt)) {
    StabilityReport r;
    r.step = step_ + 1;
    r.time = time_;
    r.field = "time_step";
    r.detail = fmt::format("time step {} is not a positive finite number", dt);
    throw StabilityError(r);
  }
  // With profiling, whatever the phases of the step did not account for (hooks, the guard's snapshot, a distributed
  // run's post-step scan and reduction) is "other".
  const auto start = profiling_ ? StepProfile::Clock::now() : StepProfile::Clock::time_point{};
  const double accounted = profiling_ ? profile_.total_seconds() : 0;
  const double halo_before = halo_ ? halo_->seconds() : 0;
  take_step(dt);
  if (profiling_ && halo_) {  // the exchanges ran inside the scatters: counted apart from P2G
    const double halo = halo_->seconds() - halo_before;
    profile_.add(StepPhase::halo, halo);
    profile_.add(StepPhase::p2g, -halo);
  }
  snapshot_.dts_since.push_back(dt);
  if (settings_.snapshot_interval > 0 && step_ % settings_.snapshot_interval == 0) take_snapshot();
  if (profiling_) {
    profile_.add(StepPhase::other, StepProfile::since(start) - (profile_.total_seconds() - accounted));
    ++profile_.steps;
    profile_.particle_updates += particle_count();
  }
}

template <int Dim>
void Simulation<Dim>::run(const std::function<void(const Simulation&)>& after_step, std::optional<Index> last_step) {
  while (!finished() && !(last_step && step_ >= *last_step)) {
    advance(time_step_toward(settings_.end_time));
    if (after_step) after_step(*this);
  }
}

template <int Dim>
void Simulation<Dim>::reset_clock() {
  time_ = 0;
  step_ = 0;
  failure_.reset();
  take_snapshot();
}

template <int Dim>
void Simulation<Dim>::take_snapshot() {
  // Copied into the buffers of the previous snapshot: no allocation (and no page faults) after the first.
  snapshot_.particles.resize(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) snapshot_.particles[b] = bodies_[b].particles;
  snapshot_.time = time_;
  snapshot_.step = step_;
  snapshot_.wave_speed = wave_speed_;
  snapshot_.dts_since.clear();
  snapshot_.tile_owner = halo_ ? halo_->owners() : std::vector<int>{};
  snapshot_.modules = StateArchive();
  for (const auto& m : hooks_.all()) m->save_state(snapshot_.modules, module_prefix(*m));
}

// Restores the snapshot and replays the steps taken since, which reproduces the state at the end of the
// last good step exactly (the run is deterministic). Costs nothing until the guard trips.
template <int Dim>
void Simulation<Dim>::roll_back_to_previous_step() {
  const std::vector<Real> replay = snapshot_.dts_since;
  for (std::size_t b = 0; b < bodies_.size(); ++b) bodies_[b].particles = snapshot_.particles[b];
  time_ = snapshot_.time;
  step_ = snapshot_.step;
  wave_speed_ = snapshot_.wave_speed;
  if (halo_) {  // the tiles' owners of the snapshot's time; a scheme's per-particle caches follow the particles
    use_owners(snapshot_.tile_owner);
    scheme_->particles_redistributed(bodies_, grid_);
  }
  for (const auto& m : hooks_.all()) m->restore_state(snapshot_.modules, module_prefix(*m));
  for (Real dt : replay) take_step(dt);
  take_snapshot();
}

template <int Dim>
bool Simulation<Dim>::replay_failure(const std::function<void(const Simulation&)>& after_step) {
  if (!failure_) return false;
  const Snapshot start = *failure_;
  for (std::size_t b = 0; b < bodies_.size(); ++b) bodies_[b].particles = start.particles[b];
  time_ = start.time;
  step_ = start.step;
  wave_speed_ = start.wave_speed;
  if (halo_) {
    use_owners(start.tile_owner);
    scheme_->particles_redistributed(bodies_, grid_);
  }
  for (const auto& m : hooks_.all()) m->restore_state(start.modules, module_prefix(*m));
  if (after_step) after_step(*this);
  for (std::size_t k = 0; k < start.dts_since.size(); ++k) {
    take_step(start.dts_since[k], k + 1 < start.dts_since.size());
    if (after_step) after_step(*this);
  }
  return true;
}

template <int Dim>
StabilityReport Simulation<Dim>::diagnose(Real dt) const {
  StabilityReport r;
  const auto& g = grid_.geometry;
  const Vec<Dim> lower = boundary_->keep_lower(g), upper = boundary_->keep_upper(g);  // open on outflow faces
  const bool axisymmetric = g.coordinates == Coordinates::axisymmetric;
  for (const auto& b : bodies_) {
    const auto& p = b.particles;
    const Real* hoop = axisym::hoop_stretch_of(p);
    for (Index i = 0; i < p.size(); ++i) {
      auto fail = [&](const char* field, std::string detail) {
        r.body = b.name;
        r.particle = p.id[i];
        r.field = field;
        r.detail = std::move(detail);
      };
      Vec<Dim> x = p.x[i];
      if (!x.allFinite()) {
        fail("position", "not finite");
      } else if (scheme_->positions_must_stay_in_grid() &&
                 ((x.array() < lower.array()).any() || (x.array() > upper.array()).any())) {
        int face = 0;  // the first face crossed, in face order
        for (int d = Dim - 1; d >= 0; --d) {
          if (x[d] > upper[d]) face = 2 * d + 1;
          if (x[d] < lower[d]) face = 2 * d;
        }
        fail("position",
             fmt::format("x = ({}) left the grid box through {}, a face that does not let material out",
                         fmt::join(x.data(), x.data() + Dim, ", "), face_names[static_cast<std::size_t>(face)]));
        r.face = face_names[static_cast<std::size_t>(face)];
      } else if (axisymmetric && scheme_->positions_must_stay_in_grid() && !(x[0] > 0)) {
        fail("position", fmt::format("r = {:.6g} m: on or across the axis of the axisymmetric grid", x[0]));
      } else if (!p.v[i].allFinite()) {
        fail("velocity", "not finite");
      } else if (const Real J = axisym::volume_ratio(p, i, hoop); !(J > 0)) {
        fail("deformation_gradient", fmt::format("det F = {:.6g} (inverted or degenerate)", J));
      } else if (!p.stress[i].full().allFinite()) {
        fail("stress", "not finite");
      } else {
        continue;
      }
      r.detail += fmt::format(" (dt = {:.6g} s; stable dt = {:.6g} s)", dt, stable_time_step());
      return r;
    }
  }
  r.body = "?";
  r.field = "unknown";
  r.detail = "a module reported an invalid state";
  return r;
}

template <int Dim>
EnergyBalance Simulation<Dim>::energy() const {
  EnergySums e;
  for (const auto& b : bodies_) add_body_energy(b, settings_.transfer.gravity, hooks_.all(), e);
  if (comm_) e.reduce(*comm_);
  return e.value();
}

template <int Dim>
EnergyBalance Simulation<Dim>::body_energy(const Body<Dim>& body) const {
  EnergySums e;
  add_body_energy(body, settings_.transfer.gravity, hooks_.all(), e);
  if (comm_) e.reduce(*comm_);
  return e.value();
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

}  // namespace mpm
