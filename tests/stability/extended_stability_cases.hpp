#pragma once
/// \file extended_stability_cases.hpp
/// The extended stiff and extreme cases, added to stability_cases(): a nu = 0.49999 block under its
/// own weight with every scheme (volumetric locking: the pressure checkerboard), a steel disk at 10 km/s with the
/// Johnson-Cook / Mie-Gruneisen material (does the EOS hold it or the guard stop it), two disks of density ratio
/// 1e4 in multi-velocity contact, and 1e5 steps at the CFL bound (cfl 1) with every explicit scheme. Each outcome
/// carries what the run did (StabilityOutcome::measured and ::measures) and what the user was told (the guard's
/// message, the energy sentinel's warning in ::log and its largest ratio). Measured numbers: the tests in
/// test_locking.cpp, test_hypervelocity_eos.cpp, test_density_ratio_contact.cpp and test_cfl_bound_long_run.cpp.

#include <vector>

#include "stability_cases.hpp"

namespace mpm::verification {

/// The cases below, in the order of the issue (those of a module not compiled in are left out).
std::vector<StabilityCase> extended_stability_cases();

}  // namespace mpm::verification
