#pragma once
// The fluids' nodal average of J as a module without a scene section (volume_smoothing_module.cpp).

namespace mpm::fluids {

/// The material key that turns the average on (newtonian_fluid's `pressure_smoothing`).
inline constexpr const char* smoothing_key = "pressure_smoothing";

/// Registers the preparer that adds mpm::fluids::VolumeSmoothing to a run whose fluids ask for it.
void register_volume_smoothing();

}  // namespace mpm::fluids
