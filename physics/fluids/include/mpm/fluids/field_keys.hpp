#pragma once
/// \file field_keys.hpp
/// The particle field of the fluids module.

#include "mpm/core/types.hpp"
#include "mpm/particles/field_key.hpp"

namespace mpm::fluids::keys {

/// Specific internal energy e of an ideal gas particle, J/kg (eq. 5.33).
inline constexpr FieldKey<Real> internal_energy{"internal_energy"};

}  // namespace mpm::fluids::keys
