#pragma once
/// \file field_keys.hpp
/// The particle fields of the thermal module (the shared `temperature` is in mpm/field_keys.hpp).

#include "mpm/core/types.hpp"
#include "mpm/particles/field_key.hpp"

namespace mpm::thermal::keys {

/// q_p = -k grad T, W/m^2 (the flux of the next step's heat flow).
template <int Dim>
inline constexpr FieldKey<VecU<Dim>> heat_flux{"heat_flux"};
/// Index of the fixed-temperature region the particle lies in, -1 for none.
inline constexpr FieldKey<int> thermal_region{"thermal_region"};
/// The temperature change of the last thermal step, K (for the thermal expansion).
inline constexpr FieldKey<Real> temperature_increment{"temperature_increment"};

}  // namespace mpm::thermal::keys
