#pragma once
/// \file step_profile.hpp
/// Where the wall time of a run goes: P2G, grid update, G2P, stress update, output and the rest (sorting,
/// binning, snapshots for the stability guard, module hooks). `mpm run --profile` and
/// `bench_throughput --profile` print it.
///
/// The kernels time their phases only when StepContext::profile is set (Simulation::enable_profiling): a
/// PhaseTimer on a null profile is one pointer test and no clock read, so a run without profiling pays
/// nothing measurable (docs/PERFORMANCE.md gives the measurement).

#include <array>
#include <atomic>
#include <chrono>
#include <string>
#include <string_view>

namespace mpm {

enum class StepPhase : int { p2g, grid_update, g2p, stress_update, halo, migrate, rebalance, sort, output, other };
inline constexpr int step_phase_count = 10;
/// Printed names, in the order of StepPhase.
inline constexpr std::array<std::string_view, step_phase_count> step_phase_names = {
    "P2G", "grid update", "G2P", "stress update", "halo", "migrate", "rebalance", "sort", "output", "other"};

/// Wall seconds per phase, summed over the steps. Phases are timed on the calling thread around the
/// parallel loops, so they are wall time whatever the thread count.
///   P2G: binning and every particle-to-grid scatter (MUSL's and TLMPM's second mapping included);
///   grid update: nodal velocities, boundary conditions and tractions, grid-velocity module hooks;
///   G2P: particle velocity, position, F (and L) from the grid;
///   stress update: the materials' constitutive update;
///   halo: a distributed run's ghost-node exchanges (waiting for the other ranks included; taken out of P2G);
///   migrate: a distributed run's migration of particles between ranks after every step;
///   rebalance: a distributed run's balance check every --rebalance-every steps (slab costs summed over the
///     ranks) and, when it deals the slabs anew, the migration that follows;
///   sort: the reordering of the particles by cell every `solver.sort_interval` steps (order_by_cell and the
///     gather of every field; a distributed run's scatter keys);
///   output: writing frames (added by the run loop);
///   other: the rest of Simulation::advance (the guard's snapshots, other hooks; a distributed run's post-step scan
///     and the step's reduction, waiting for the slower rank included).
struct StepProfile {
  using Clock = std::chrono::steady_clock;

  std::array<double, step_phase_count> seconds{};
  long long steps = 0;
  long long particle_updates = 0;  ///< particles x steps

  void add(StepPhase phase, double s) { seconds[static_cast<int>(phase)] += s; }
  double operator[](StepPhase phase) const { return seconds[static_cast<int>(phase)]; }
  double stepping_seconds() const;  ///< every phase but output
  double total_seconds() const;     ///< every phase
  void clear() { *this = StepProfile{}; }
  static double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
};

/// Adds the wall time of its scope to one phase of `profile`; does nothing when `profile` is null.
class PhaseTimer {
 public:
  PhaseTimer(StepProfile* profile, StepPhase phase) : profile_(profile), phase_(phase) {
    if (profile_) start_ = StepProfile::Clock::now();
  }
  ~PhaseTimer() { stop(); }
  /// Ends the timing before the end of the scope (for phases that follow each other without braces).
  void stop() {
    if (profile_) profile_->add(phase_, StepProfile::since(start_));
    profile_ = nullptr;
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  StepProfile* profile_;
  StepPhase phase_;
  StepProfile::Clock::time_point start_{};
};

/// G2P and the stress update run fused, block by block on each thread (explicit_step.hpp), so their wall
/// time cannot be taken apart by a timer around a loop. Each block adds the seconds of its two halves here
/// (summed over threads: CPU time); the fused loop's wall time is then split in that proportion.
struct FusedSplit {
  std::atomic<double> transfer{0}, stress{0};
  /// Adds wall * transfer / (transfer + stress) to G2P and the rest to the stress update.
  void distribute(StepProfile& profile, double wall) const;
};

/// The profile as a table: phase, seconds, share of the total, nanoseconds per particle-update.
std::string format_profile(const StepProfile& profile);

}  // namespace mpm
