#pragma once
/// \file register.hpp
/// Registration of the thermal module: the `thermal:` scene section, the per-material keys
/// (thermal_conductivity, specific_heat, thermal_expansion, room_temperature) and the builder of the heat
/// conduction module, which is constructed only for a scene with a `thermal:` section. Called by the
/// generated mpm::app::register_modules() when compiled in (CMake option MPM_WITH_THERMAL).

namespace mpm::thermal {

/// Registers the section, the material keys and the module builder (idempotent).
void register_module();

}  // namespace mpm::thermal
