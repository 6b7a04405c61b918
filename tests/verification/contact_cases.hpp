#pragma once
/// \file contact_cases.hpp
/// The contact module's cases in the verification catalogue (compiled only with MPM_WITH_CONTACT): an
/// elastic block sliding on a rigid floor (contact plane) under gravity tilted by 30 degrees, mu = 0.2;
/// error = relative error of the sliding acceleration against g (sin theta - mu cos theta) = 3.2059 m/s^2.
/// Resolution = cells across the block height (0.1 m).

#include <vector>

#include "catalogue.hpp"

namespace mpm::verification {

void add_contact_cases(std::vector<VerificationCase>& list, bool quick, int refinements);

}  // namespace mpm::verification
