#pragma once
/// \file register.hpp
/// Registration of the implicit module: the scheme `implicit` (scheme_registry.hpp) with its `solver.implicit:`
/// keys and refusals. Called by the generated mpm::app::register_modules() when compiled in (CMake option
/// MPM_WITH_IMPLICIT). A scene with another scheme constructs nothing of it.

namespace mpm::implicit {

/// Registers the scheme (idempotent).
void register_module();

}  // namespace mpm::implicit
