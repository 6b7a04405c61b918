#pragma once
/// \file register.hpp
/// Registration of the user_material module: the material model `user` (a material law from a shared library:
/// Abaqus VUMAT or UMAT, or this program's C interface mpm_user_material.h), with its parameters and keys (for the
/// scene loader and the generated reference) and builders. Called by the generated mpm::app::register_modules()
/// when the module is compiled in (CMake option MPM_WITH_USER_MATERIAL).

namespace mpm::user_material {

/// Adds the model `user` to the material catalog (idempotent).
void register_module();

}  // namespace mpm::user_material
