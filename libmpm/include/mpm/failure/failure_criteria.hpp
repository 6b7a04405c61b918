#pragma once
/// \file failure/failure_criteria.hpp
/// When a particle fails and what it then becomes (a material's `failure:` block, docs/scene-reference.md,
/// materials): the criteria impact codes offer (LS-DYNA's MAT_ADD_EROSION, Abaqus/Explicit's element deletion),
/// each decided from the particle's own state at the end of a step (docs/theory.md §16, eqs. 16.1-16.3), so a
/// particle fails at the same step whatever the thread or rank count. Several criteria may be given; the first met,
/// in the order of FailureCriterion, fails the particle.

#include <array>
#include <optional>
#include <string_view>

#include "mpm/core/types.hpp"

namespace mpm {

/// What a failed particle becomes.
enum class FailureAction {
  /// Leaves the run at the end of the step it failed in; its mass, momentum and energies are booked as eroded
  /// (energy.csv's eroded_* columns). The default, as LS-DYNA's erosion and Abaqus/Explicit's element deletion.
  erode,
  /// Keeps its mass and carries only compressive pressure from then on: no deviatoric stress, no tension (eq. 16.2).
  fail,
};

/// The criteria, in the order they are tested (and listed in the scene reference).
enum class FailureCriterion {
  damage,            ///< Johnson-Cook damage D >= 1 (plasticity's damage, eq. B.16)
  plastic_strain,    ///< equivalent plastic strain eps_p >= the limit
  principal_strain,  ///< largest principal logarithmic strain ln(lambda_max) >= the limit
  principal_stress,  ///< largest principal Cauchy stress >= the limit, Pa
  spall_pressure,    ///< tensile mean stress tr(sigma) / 3 >= the limit, Pa (the spall strength)
  volume_ratio,      ///< J = det F below min_volume_ratio or above max_volume_ratio
  time_step,         ///< the particle's own stable time step (eq. 16.3) below the floor, s
};
inline constexpr int failure_criterion_count = 7;

/// The scene's name of a criterion (its key in `failure:`; `volume_ratio` for the pair of bounds).
constexpr std::string_view criterion_name(FailureCriterion c) {
  constexpr std::array<std::string_view, failure_criterion_count> names{
      "damage",         "plastic_strain", "principal_strain", "principal_stress",
      "spall_pressure", "volume_ratio",   "min_time_step"};
  return names[static_cast<std::size_t>(c)];
}

/// One material's `failure:` block. An absent limit is not tested.
struct FailureCriteria {
  bool damage = false;                   ///< fail at D >= 1
  std::optional<Real> plastic_strain;    ///< -
  std::optional<Real> principal_strain;  ///< -
  std::optional<Real> principal_stress;  ///< Pa
  std::optional<Real> spall_pressure;    ///< Pa (> 0: a tension)
  std::optional<Real> min_volume_ratio;  ///< -
  std::optional<Real> max_volume_ratio;  ///< -
  std::optional<Real> min_time_step;     ///< s
  FailureAction action = FailureAction::erode;

  bool needs_damage() const { return damage; }
  bool needs_plastic_strain() const { return plastic_strain.has_value(); }
  bool needs_principal_strain() const { return principal_strain.has_value(); }
  bool needs_principal_stress() const { return principal_stress.has_value(); }
  bool needs_time_step() const { return min_time_step.has_value(); }
};

/// A particle's state as the criteria read it. Measures a criterion of the material does not test may be left 0.
struct FailureMeasures {
  Real damage = 0;            ///< D, -
  Real plastic_strain = 0;    ///< eps_p, -
  Real principal_strain = 0;  ///< ln(lambda_max), -
  Real principal_stress = 0;  ///< Pa
  Real mean_stress = 0;       ///< tr(sigma) / 3, Pa (positive in tension)
  Real volume_ratio = 1;      ///< J
  Real time_step = 0;         ///< s (eq. 16.3)
};

/// The first criterion of `c` that `m` meets (eq. 16.1), or nothing. A limit is met when reached (>=, or <= for
/// the lower bounds), so that a criterion set exactly at the particle's value fails it.
inline std::optional<FailureCriterion> first_met(const FailureCriteria& c, const FailureMeasures& m) {
  if (c.damage && m.damage >= 1) return FailureCriterion::damage;
  if (c.plastic_strain && m.plastic_strain >= *c.plastic_strain) return FailureCriterion::plastic_strain;
  if (c.principal_strain && m.principal_strain >= *c.principal_strain) return FailureCriterion::principal_strain;
  if (c.principal_stress && m.principal_stress >= *c.principal_stress) return FailureCriterion::principal_stress;
  if (c.spall_pressure && m.mean_stress >= *c.spall_pressure) return FailureCriterion::spall_pressure;
  if ((c.min_volume_ratio && m.volume_ratio <= *c.min_volume_ratio) ||
      (c.max_volume_ratio && m.volume_ratio >= *c.max_volume_ratio))
    return FailureCriterion::volume_ratio;
  if (c.min_time_step && m.time_step <= *c.min_time_step) return FailureCriterion::time_step;
  return std::nullopt;
}

/// The stress a failed particle (FailureAction::fail) carries (eq. 16.2): the pressure p = -tr(sigma) / 3 where it
/// compresses, nothing where it would pull: sigma_failed = -max(p, 0) 1.
template <int Dim>
inline SymTensor<Dim> pressure_only(const SymTensor<Dim>& s) {
  const Real pressure = -(s.c[0] + s.c[1] + s.c[2]) / 3;
  SymTensor<Dim> out;
  const Real kept = pressure > 0 ? -pressure : Real(0);
  out.c[0] = out.c[1] = out.c[2] = kept;
  return out;
}

}  // namespace mpm
