#pragma once
/// \file fluids_cases.hpp
/// The fluids module's cases in the verification catalogue (compiled only with MPM_WITH_FLUIDS): Sod's
/// shock tube (sod.hpp) at t = 0.143 with artificial viscosity c_1 = 1, c_2 = 2, every updated-Lagrangian
/// scheme with every 1D shape function (TLMPM is a solid scheme: a gas needs the current configuration).
/// Error = L1 of the particle density against the exact solution, normalised by the density jump.

#include <vector>

#include "catalogue.hpp"

namespace mpm::verification {

void add_fluids_cases(std::vector<VerificationCase>& list, bool quick, int refinements);

}  // namespace mpm::verification
