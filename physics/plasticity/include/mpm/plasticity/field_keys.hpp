#pragma once
/// \file field_keys.hpp
/// The particle field of the plasticity module (the shared `temperature` is in mpm/field_keys.hpp).

#include "mpm/field_key.hpp"
#include "mpm/plasticity/elastoplastic.hpp"

namespace mpm::plasticity::keys {

/// The history of every material point (PlasticState, read and written together).
template <int Dim>
inline constexpr FieldKey<PlasticState<Dim>> plastic_state{"plasticity"};

}  // namespace mpm::plasticity::keys
