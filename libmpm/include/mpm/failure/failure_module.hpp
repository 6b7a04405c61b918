#pragma once
/// \file failure/failure_module.hpp
/// Failure and erosion as one module of the step (module.hpp), built for a scene in which a material has a
/// `failure:` block. At the end of every step it tests each particle of those materials' bodies against its
/// material's criteria (failure_criteria.hpp), from the particle's own state only, so that the same particles fail at
/// the same step for any thread or rank count. A particle that meets one either erodes (leaves its body; its mass,
/// momentum and energies are booked, removal/removed_particles.hpp, and the energy sentinel adds them back, eq. 8.4)
/// or fails (keeps its mass, carries only compressive pressure: FailingMaterial). When particles eroded, the step's
/// wave-speed bound is taken again from the remaining ones, so that the next time step is theirs.

#include <array>
#include <string>
#include <vector>

#include "mpm/failure/failure_criteria.hpp"
#include "mpm/removal/removed_particles.hpp"
#include "mpm/simulation/module.hpp"

namespace mpm {

/// The failure criteria of one body (the criteria of its material).
struct BodyFailure {
  int body = 0;  ///< Body::index
  FailureCriteria criteria;
};

/// What failed since t = 0, per body with criteria: the books of its eroded particles and the count per criterion.
struct FailureBooks {
  int body = 0;
  RemovedBook eroded;
  std::array<std::int64_t, failure_criterion_count> failed_by{};  ///< particles per criterion (eroded or failed)
  std::int64_t failed_in_place = 0;                               ///< action fail: particles that carry only pressure
};

template <int Dim>
class FailureModule final : public Module<Dim> {
 public:
  /// `cfl`: the time step factor, for the particles' own stable time step (eq. 16.3).
  FailureModule(std::vector<BodyFailure> bodies, Real cfl);

  std::string_view name() const override { return "failure"; }
  unsigned phases() const override { return phase_end_of_step; }
  /// Each particle's failure is decided from its own state; the books are reduced over the ranks (exact sums).
  std::string why_not_distributed() const override { return {}; }
  void end_of_step(StepContext<Dim>& ctx) override;
  /// J: the energy the eroded particles took along (eq. 8.4), the same on every rank.
  Real removed_energy() const override;
  void save_state(StateArchive& archive, const std::string& prefix) const override;
  void restore_state(const StateArchive& archive, const std::string& prefix) override;

  /// Whether a body's material erodes (the energy.csv columns eroded_*).
  bool erodes() const;
  /// Per body with criteria, in body order (the same on every rank).
  const std::vector<FailureBooks>& books() const { return books_; }
  /// The eroded books of every body together.
  RemovedBook eroded() const;
  /// One line per body for the run's final summary ("failure of body 'plate': 120 particles eroded (damage 118,
  /// ...), mass 0.3 kg, ...").
  std::vector<std::string> summary(const std::vector<std::string>& body_names) const;

 private:
  /// Fills measures_ for the particles of `body` (only the measures its criteria read).
  void measure(const Body<Dim>& body, const FailureCriteria& c, const GridGeometry<Dim>& g);

  std::vector<BodyFailure> bodies_;
  Real cfl_;
  std::vector<FailureBooks> books_;
  ParticleRemover<Dim> remover_;
  // scratch, kept between steps
  std::vector<FailureMeasures> measures_;
  std::vector<double> values_;
  std::vector<Real> wave_speed_;
  std::vector<Index> fail_, erode_;
};

}  // namespace mpm
