#pragma once
/// \file field_keys.hpp
/// The particle field of the fluids module.

#include "mpm/core/types.hpp"
#include "mpm/particles/field_key.hpp"

namespace mpm::fluids::keys {

/// Specific internal energy e of an ideal gas particle, J/kg (eq. 5.33).
inline constexpr FieldKey<Real> internal_energy{"internal_energy"};

}  // namespace mpm::fluids::keys

namespace mpm::fluids::keys {

/// Pressure p of an incompressible fluid particle, Pa: the projection's multiplier of its cell (eq. 21.3), kept so
/// that the -p I the projection adds to the stress at the end of a step comes off again before the next transfer.
inline constexpr FieldKey<Real> projected_pressure{"projected_pressure"};

}  // namespace mpm::fluids::keys
