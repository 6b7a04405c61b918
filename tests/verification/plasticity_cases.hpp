#pragma once
/// \file plasticity_cases.hpp
/// The plasticity module's cases in the verification catalogue (compiled only with MPM_WITH_PLASTICITY):
/// the Taylor anvil (taylor_anvil.hpp) with TLMPM (hat) and MUSL (hat, cubic B-spline), error Delta of
/// review eq. 6.19 against the experiment. Resolution = cells across 8 mm (h = 8 mm / n).

#include <vector>

#include "catalogue.hpp"

namespace mpm::verification {

void add_plasticity_cases(std::vector<VerificationCase>& list, bool quick, int refinements);

}  // namespace mpm::verification
