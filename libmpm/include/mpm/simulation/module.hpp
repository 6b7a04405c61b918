#pragma once
/// \file module.hpp
/// Optional physics joins the step through phases, in the spirit of LAMMPS fix masks. A module says
/// which phases it needs; the simulation keeps one list per phase, so a phase no module subscribed to
/// costs one empty-loop test per step, and a module the scene does not name is never constructed.

#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mpm/simulation/energy.hpp"
#include "mpm/simulation/step_context.hpp"

namespace mpm {

class StateArchive;

/// Stages at which the nodal velocities are (re)computed, for modules that constrain them (contact).
enum class GridStage {
  mapped,    ///< after P2G: v^t from the mapped momentum
  updated,   ///< after the momentum update: v^{t+dt} (USL) or the trial v~ (MUSL)
  remapped,  ///< MUSL only: after the second mapping, v^{t+dt}
};

enum Phase : unsigned {
  phase_after_p2g = 1u << 0,
  phase_grid_velocity = 1u << 1,
  phase_after_g2p = 1u << 2,
  phase_after_stress = 1u << 3,
  phase_end_of_step = 1u << 4,
  phase_before_step = 1u << 5,
};

template <int Dim>
class Module {
 public:
  virtual ~Module() = default;
  virtual std::string_view name() const = 0;
  /// Bitwise OR of the Phase values this module implements.
  virtual unsigned phases() const = 0;
  virtual void after_p2g(StepContext<Dim>&) {}
  virtual void on_grid_velocity(StepContext<Dim>&, GridStage) {}
  virtual void after_g2p(StepContext<Dim>&) {}
  virtual void after_stress(StepContext<Dim>&) {}
  virtual void end_of_step(StepContext<Dim>&) {}
  /// Before any transfer of the step (e.g. to set the particle field "body_force" for time t).
  virtual void before_step(StepContext<Dim>&) {}
  /// Empty when the module keeps its results independent of the rank count in a distributed run (its scatters
  /// exchange ghost nodes, its sums are reduced through StepContext::comm); else why not, for the message with
  /// which Simulation::distribute refuses the run.
  virtual std::string why_not_distributed() const { return "its scatters and sums have no ghost exchange"; }
  /// False on every rank but 0 of a distributed run (Simulation::distribute, and before a restart's
  /// restore_state): the module computes alike but leaves its own files (contact's force CSV) to rank 0.
  virtual void set_writes_files(bool /*on*/) {}
  /// The largest stable time step this module allows (s); infinity when it imposes none.
  virtual Real stable_time_step(const std::vector<Body<Dim>>&) const { return std::numeric_limits<Real>::infinity(); }
  /// What stable_time_step() bounds, for the log ("diffusion bound h^2 rho c / (2 dim k)").
  virtual std::string_view time_step_bound() const { return name(); }
  /// Adds the module's share of the conservation audit of one body (e.g. its thermal energy) to `e`, one
  /// term per particle (called for every body in turn: energy.csv and the per-body energy histories).
  virtual void add_energy(const Body<Dim>&, EnergySums&) const {}
  /// J: the energy (EnergyBalance::total() terms) of the particles this module took out of the run since t = 0
  /// (erosion), or dissipated outside the audit (local damping, eq. 2.75), the same on every rank; the energy sentinel
  /// adds it to its balance (docs/theory.md eq. 8.4).
  virtual Real removed_energy() const { return 0; }
  /// The energy.csv column of the module's own books (local damping: `damped_energy`; the thermal strain's work:
  /// `thermal_expansion_work`), empty when it keeps none; written after the outflow and eroded columns.
  virtual std::string_view energy_column() const { return {}; }
  /// J, that column's value, the same on every rank: by default removed_energy() (what the module took out).
  virtual Real energy_column_value() const { return removed_energy(); }
  /// What the module carries from one step to the next outside the particle fields (positions of moving
  /// planes, force sums, the length of its CSV file, ...), as entries `prefix`NAME (state_archive.hpp): for
  /// checkpoints and for the stability guard's snapshots. A module whose state is all in particle fields
  /// saves nothing.
  virtual void save_state(StateArchive&, const std::string& /*prefix*/) const {}
  /// Restores what save_state() saved (a restart, or the guard's roll-back to its snapshot); throws
  /// ArchiveError when an entry is missing.
  virtual void restore_state(const StateArchive&, const std::string& /*prefix*/) {}
};

/// Where a module's state goes in a StateArchive: "modules/NAME/" (module names are unique in a run).
template <int Dim>
std::string module_prefix(const Module<Dim>& m) {
  return "modules/" + std::string(m.name()) + "/";
}

/// The modules of a run, sorted by phase.
template <int Dim>
class ModuleHooks {
 public:
  void add(std::shared_ptr<Module<Dim>> m) {
    const unsigned p = m->phases();
    if (p & phase_after_p2g) after_p2g_.push_back(m.get());
    if (p & phase_grid_velocity) grid_velocity_.push_back(m.get());
    if (p & phase_after_g2p) after_g2p_.push_back(m.get());
    if (p & phase_after_stress) after_stress_.push_back(m.get());
    if (p & phase_end_of_step) end_of_step_.push_back(m.get());
    if (p & phase_before_step) before_step_.push_back(m.get());
    all_.push_back(std::move(m));
  }
  void after_p2g(StepContext<Dim>& c) {
    for (auto* m : after_p2g_) m->after_p2g(c);
  }
  void grid_velocity(StepContext<Dim>& c, GridStage s) {
    for (auto* m : grid_velocity_) m->on_grid_velocity(c, s);
  }
  void after_g2p(StepContext<Dim>& c) {
    for (auto* m : after_g2p_) m->after_g2p(c);
  }
  void after_stress(StepContext<Dim>& c) {
    for (auto* m : after_stress_) m->after_stress(c);
  }
  void before_step(StepContext<Dim>& c) {
    for (auto* m : before_step_) m->before_step(c);
  }
  void end_of_step(StepContext<Dim>& c) {
    for (auto* m : end_of_step_) m->end_of_step(c);
  }
  /// Takes `m` out of every phase and of all().
  void remove(const Module<Dim>* m) {
    for (auto* list : {&after_p2g_, &grid_velocity_, &after_g2p_, &after_stress_, &end_of_step_, &before_step_})
      std::erase(*list, m);
    std::erase_if(all_, [&](const std::shared_ptr<Module<Dim>>& k) { return k.get() == m; });
  }
  bool has_after_g2p() const { return !after_g2p_.empty(); }
  const std::vector<std::shared_ptr<Module<Dim>>>& all() const { return all_; }

 private:
  std::vector<Module<Dim>*> after_p2g_, grid_velocity_, after_g2p_, after_stress_, end_of_step_, before_step_;
  std::vector<std::shared_ptr<Module<Dim>>> all_;
};

}  // namespace mpm
