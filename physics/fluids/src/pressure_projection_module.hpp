#pragma once
// The incompressible fluids' pressure projection as a module without a scene section (pressure_projection_module.cpp).

namespace mpm::fluids {

/// Registers the preparer that adds mpm::fluids::PressureProjection to a run with an `incompressible_fluid` body.
void register_pressure_projection();

}  // namespace mpm::fluids
