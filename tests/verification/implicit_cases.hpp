#pragma once
/// \file implicit_cases.hpp
/// The implicit scheme's cases in the verification catalogue (compiled only with MPM_WITH_IMPLICIT): the
/// vibrating bar of review §6.1.1 (mode 1, eq. 6.4) with hencky_j2 (K = 40, G = 45: the constrained modulus 100
/// of the linear case), at a strain amplitude of 1e-4, by the implicit scheme at twice the explicit bound
/// (dt = 2 h / c) and by MUSL (hats) at dt = 0.1 h / c, so that the error-against-run-time report compares the
/// two on one material. Resolution = cells along the bar (25 m).

#include <vector>

#include "catalogue.hpp"

namespace mpm::verification {

void add_implicit_cases(std::vector<VerificationCase>& list, bool quick, int refinements);

}  // namespace mpm::verification
