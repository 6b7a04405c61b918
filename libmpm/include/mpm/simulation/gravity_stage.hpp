#pragma once
/// \file gravity_stage.hpp
/// The gravity stage (`solver.gravity_stage`; docs/theory.md §20): before t = 0 the bodies settle under gravity with
/// the local damping of eq. 2.74 and PIC transfers until the unbalanced force ratio (eq. 20.3) has stayed below the
/// tolerance for `settled_steps` steps in a row; the run then starts from that state at rest. Each step of the stage
/// runs from t = -dt to 0, so the clock stays at 0 and the face and set conditions end every step with their values of
/// t = 0 (the velocities the positions move with); at its end the particles' velocities (and APIC's and PolyPIC's
/// modes) are set to zero, the clock to t = 0 and step 0, and the displacement's reference positions to the settled
/// ones (not with TLMPM, whose reference configuration is its weights'). Everything the material points carry (stress,
/// plastic strain, their history) is kept: the run continues the stage's state. The builder runs it before it adds the
/// energy books (damping, erosion, the sentinel), so E(0) is the settled state.

#include <string>
#include <vector>

#include "mpm/core/types.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm {

/// What the stage does (the scene's solver.gravity_stage, GravityStageDescription).
struct GravityStageSettings {
  Real damping = 0.8;        ///< alpha of eq. 2.74 during the stage, in (0, 1)
  Real tolerance = 1e-4;     ///< of the unbalanced force ratio, eq. 20.3
  Index max_steps = 100000;  ///< the stage gives up after this many steps
};

/// One step of the stage.
struct GravityStageRow {
  Index step = 0;
  Real dt = 0;              ///< s
  Real ratio = 0;           ///< the unbalanced force ratio of eq. 20.3 at the step
  Real kinetic_energy = 0;  ///< J (per metre in 2D, per radian axisymmetric), after the step
};

/// How the stage went.
struct GravityStageReport {
  bool converged = false;  ///< the ratio stayed below the tolerance for settled_steps steps
  Index steps = 0;
  Real ratio = 0;  ///< of the last step
  Real tolerance = 0;
  /// m: the largest distance a particle moved during the stage (the displacement the run then counts from 0; a
  /// strength-reduction study reads it against the reduction factor)
  Real largest_displacement = 0;
  std::vector<GravityStageRow> rows;  ///< one per step
  /// "gravity stage: at rest after 812 steps (unbalanced force ratio 9.1e-05 < 0.0001 for 10 steps; largest
  /// displacement 0.00297 m)" or what it reached.
  std::string summary() const;
};

/// Steps the stage must stay below the tolerance: a single step can pass through a small ratio while the bodies
/// still swing (the force reverses with the motion).
inline constexpr Index settled_steps = 10;

/// Runs the stage on a built simulation that has not stepped yet (one process: before Simulation::distribute) and
/// starts its clock anew. Throws StabilityError when the guard trips during the stage.
template <int Dim>
GravityStageReport run_gravity_stage(Simulation<Dim>& sim, const GravityStageSettings& stage);

}  // namespace mpm
