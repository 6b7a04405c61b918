#pragma once
/// \file energy_hints.hpp
/// The one table of documented instabilities: for a scheme, shape function and transfer (and whether a contact
/// module runs), the nearest measured cause of an energy gain or a guard stop, the remedy, and the measurement
/// it rests on (docs/VERIFICATION.md, "Stiff and extreme cases" and "Energy sentinel"; the READMEs cited).
/// The energy sentinel's warning (energy_sentinel.hpp) and the flight recorder's diagnosis.txt quote it; the
/// table in docs/VERIFICATION.md is printed from it (`mpm reference --energy-hints`).

#include <span>
#include <string>
#include <string_view>

#include "mpm/core/types.hpp"
#include "mpm/schemes/scheme_traits.hpp"
#include "mpm/simulation/solver_options.hpp"

namespace mpm {

/// What a hint is matched against: the run's numerical method. The rows ask the scheme's traits
/// (scheme_traits.hpp; the defaults are MUSL's) and the shape function's (ShapeFunctionInfo), never their names.
struct HintContext {
  SchemeTraits scheme;                    ///< the traits of the run's scheme (scheme_of(solver).traits)
  std::string shape_function = "linear";  ///< a name of shape_function_names()
  VelocityTransfer transfer = VelocityTransfer::flip;
  Real flip_fraction = 1;
  bool contact = false;   ///< the multi-velocity contact module runs
  bool fixed_dt = false;  ///< solver.dt rather than solver.cfl
  /// A material keeps the full F of a law that reads J alone (volumetric_deformation: 0, a fluid's default).
  bool fluid_full_deformation = false;
};

/// What went wrong: the energy balance grew (the sentinel), the stability guard stopped the run, or it stopped it
/// because a particle left the grid through a face that does not let material out (StabilityReport::face).
enum HintTrigger : unsigned { trigger_energy = 1u << 0, trigger_guard = 1u << 1, trigger_left_grid = 1u << 2 };

struct EnergyHint {
  std::string_view condition;           ///< the condition in words, for the docs
  unsigned triggers;                    ///< HintTrigger bits the row answers
  bool (*applies)(const HintContext&);  ///< the condition in code
  std::string_view hint;                ///< what to try
  std::string_view measurement;         ///< the measurement the hint rests on, with where it is documented
};

/// Every row, most specific first; the last one applies to everything.
std::span<const EnergyHint> energy_hints();
/// The first row for `trigger` whose condition holds.
const EnergyHint& find_energy_hint(const HintContext& context, HintTrigger trigger);
/// The table as Markdown (docs/VERIFICATION.md, "Energy sentinel").
std::string energy_hint_table();

}  // namespace mpm
