#pragma once
/// \file energy_sentinel.hpp
/// The energy sentinel (`solver.energy_tolerance`, `solver.on_energy_drift`; docs/theory.md §8): every
/// `interval` steps (50; the work below is accumulated every step), the balance
///   B(t) = E(t) - E(0) - W(t) + E_out(t),   E = kinetic + strain (with a gas's internal energy) + gravity
///                                             potential + plastic work (dissipation, kept as energy),
/// where W is the work done on the bodies by the face conditions (prescribed velocities and tractions,
/// GridBoundary::work), by moving rigid partners (reaction_provider.hpp: F . V dt) and by the particle field
/// "body_force" when a module sets it (sum m b . (v(t) + v(t + dt)) / 2 dt), and E_out the energy E of the particles
/// that left through outflow faces, as they left (GridBoundary::outflow_energy). A stable run has
/// B <= 0 up to round-off (dissipation that is not tracked, PIC damping and friction, only lowers it); the first
/// step where B exceeds tolerance x the largest energy scale of the run so far is recorded once as an
/// EnergyDrift, with which energy grew and the hint of the one table (energy_hints.hpp). The run loop logs it
/// and, with `stop`, ends the run through the stability path.
///
/// The energy scale of a step is K + U + D + |Phi - Phi(0)| + |W| (every term that can carry the balance), its
/// largest value so far the reference of the tolerance, and never less than 1e-9 of |Phi(0)| + K(0) + U(0) + D(0)
/// (the round-off of the energies themselves). A module built by the scene builder for every scene.

#include <optional>
#include <string>
#include <vector>

#include "mpm/diagnostics/energy_hints.hpp"
#include "mpm/simulation/energy.hpp"
#include "mpm/simulation/module.hpp"
#include "mpm/simulation/reaction_provider.hpp"

namespace mpm {

/// The first step at which the balance exceeded the tolerance.
struct EnergyDrift {
  Index step = 0;
  Real time = 0;             ///< s, at the end of the step
  Real balance = 0;          ///< J
  Real tolerance = 0;        ///< J (the fraction times the largest energy scale so far)
  std::string grown;         ///< which energy grew most since the start, e.g. "strain energy +1.31 J"
  const EnergyHint* hint{};  ///< the hint table's row for the method
  /// One line: step, time, balance, tolerance, what grew, the hint and its measurement.
  std::string message() const;
};

template <int Dim>
class EnergySentinel final : public Module<Dim> {
 public:
  /// A rigid partner that can do work: the module reporting its force, its index there, and the body whose
  /// particles carry its velocity (a rigid body), or -1 (a plane: ReactionProvider::partner_velocity).
  struct Partner {
    const ReactionProvider<Dim>* provider = nullptr;
    int index = 0;
    int body = -1;
  };
  /// `fraction`: solver.energy_tolerance; `initial`: the audit of the initial state (Simulation::energy()).
  /// Steps between two audits (the work is accumulated every step): an exact audit of every particle costs
  /// about as much as a step of the cheapest schemes (an estimate, docs/theory.md §8), and the
  /// instabilities it is for grow over hundreds of steps.
  static constexpr int default_interval = 50;
  /// `interval`: steps between audits.
  EnergySentinel(Real fraction, EnergyDriftAction action, HintContext context, const EnergyBalance& initial,
                 bool boundary_work, std::vector<Partner> partners, int interval = default_interval);

  std::string_view name() const override { return "energy_sentinel"; }
  /// Its sums are reduced over the ranks (StepContext::comm); a partner's force is the same on every rank (the
  /// contact module reduces it).
  std::string why_not_distributed() const override { return {}; }
  int interval() const { return interval_; }
  unsigned phases() const override {
    return (boundary_work_ ? phase_grid_velocity : 0u) | phase_before_step | phase_end_of_step;
  }
  void before_step(StepContext<Dim>& ctx) override;
  void on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) override;
  void end_of_step(StepContext<Dim>& ctx) override;
  void save_state(StateArchive& archive, const std::string& prefix) const override;
  void restore_state(const StateArchive& archive, const std::string& prefix) override;

  EnergyDriftAction action() const { return action_; }
  /// The method the hints are matched against (the flight recorder's diagnosis quotes the same table).
  const HintContext& context() const { return context_; }
  /// The drift, from the step it was found on (stays set).
  const std::optional<EnergyDrift>& drift() const { return drift_; }
  /// B / tolerance of the last step, and its largest value over the run, with its step.
  Real last_ratio() const { return last_ratio_; }
  Real largest_ratio() const { return largest_ratio_; }
  Index largest_ratio_step() const { return largest_ratio_step_; }
  /// J: the external work so far.
  Real work() const { return work_; }

 private:
  EnergyBalance audit(const StepContext<Dim>& ctx) const;

  Real fraction_;
  EnergyDriftAction action_;
  HintContext context_;
  EnergyBalance initial_;
  bool boundary_work_;
  std::vector<Partner> partners_;
  int interval_;
  Real work_ = 0;  ///< J, W(t)
  /// J, the body force's power at the start of the step times dt / 2 (its share of the trapezoidal work)
  Real body_force_start_ = 0;
  Real scale_ = 0;       ///< J, the largest energy scale so far
  Real last_ratio_ = 0;  ///< B / tolerance of the last step
  Real largest_ratio_ = 0;
  Index largest_ratio_step_ = 0;
  std::optional<EnergyDrift> drift_;
};

}  // namespace mpm
