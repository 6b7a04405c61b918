#pragma once
/// \file thermal_cases.hpp
/// The thermal module's cases in the verification catalogue (compiled only with MPM_WITH_THERMAL): the 1D bar
/// of review eq. 5.27 and the 2D plate of eq. 5.28 (heat_conduction.hpp), error = max nodal |T - T_exact|
/// relative to T1 - T0 at t = 0.05. Resolution = cells per side.

#include <vector>

#include "catalogue.hpp"

namespace mpm::verification {

void add_thermal_cases(std::vector<VerificationCase>& list, bool quick, int refinements);

}  // namespace mpm::verification
