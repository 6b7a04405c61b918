#pragma once
/// \file register.hpp
/// Registration of the soils module: the material models drucker_prager, mohr_coulomb and mu_i with their parameters
/// (for the scene loader and the generated reference) and builders, and the output field plastic_volumetric_strain.
/// Called by the generated mpm::app::register_modules() when the module is compiled in (CMake option MPM_WITH_SOILS).

namespace mpm::soils {

/// Adds drucker_prager, mohr_coulomb and mu_i to the material catalog (idempotent).
void register_module();

}  // namespace mpm::soils
