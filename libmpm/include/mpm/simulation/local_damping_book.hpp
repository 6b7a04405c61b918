#pragma once
/// \file local_damping_book.hpp
/// The books of the local non-viscous damping (`solver.damping`; local_damping.hpp, docs/theory.md eqs 2.74-2.75):
/// the energy the damping force took out of the run since t = 0,
///   D = -sum over steps, nodes and fields of dt f_d . (v^t + v^{t+dt}) / 2,
/// with v the nodal velocities after the face conditions (a held component moves with its prescribed value, where
/// the damping does not act: at rest on fixed and slip faces, so it adds nothing there). The energy sentinel adds D
/// to its balance (Module::removed_energy, eq. 8.4), energy.csv writes it as `damped_energy`, and the run's relative
/// energy change counts it: a damped run's total energy falls by D while its balance stays at the level of an
/// undamped run. Rigid bodies (contact), which move with their prescribed velocity, are neither damped nor booked.

#include <vector>

#include "mpm/simulation/module.hpp"

namespace mpm {

template <int Dim>
class LocalDampingBook final : public Module<Dim> {
 public:
  /// `alpha`: solver.damping, in (0, 1); `undamped_bodies`: the indices of the bodies that move with a prescribed
  /// velocity (contact's rigid bodies), whose own fields are not damped.
  LocalDampingBook(Real alpha, std::vector<int> undamped_bodies);
  std::string_view name() const override { return "local_damping"; }
  unsigned phases() const override { return phase_grid_velocity; }
  /// Sums over the nodes a rank owns, reduced through StepContext::comm.
  std::string why_not_distributed() const override { return {}; }
  /// At the updated stage (after the face conditions and contact): the step's damping work, eq. 2.75.
  void on_grid_velocity(StepContext<Dim>& ctx, GridStage stage) override;
  /// J: D, the energy dissipated by the damping since t = 0 (the same on every rank).
  Real removed_energy() const override { return dissipated_; }
  /// energy.csv's `damped_energy`: total_energy + damped_energy is E(0) + W.
  std::string_view energy_column() const override { return "damped_energy"; }
  Real dissipated() const { return dissipated_; }
  Real alpha() const { return alpha_; }
  void save_state(StateArchive& archive, const std::string& prefix) const override;
  void restore_state(const StateArchive& archive, const std::string& prefix) override;

 private:
  Real alpha_;
  std::vector<int> undamped_bodies_;
  Real dissipated_ = 0;  ///< J
};

}  // namespace mpm
