#pragma once
/// \file field_keys.hpp
/// The particle fields of the plasticity module (the shared `temperature` is in mpm/field_keys.hpp).

#include "mpm/particles/field_key.hpp"
#include "mpm/plasticity/elastoplastic.hpp"
#include "mpm/plasticity/hencky_j2.hpp"

namespace mpm::plasticity::keys {

/// The history of every material point (PlasticState, read and written together).
template <int Dim>
inline constexpr FieldKey<PlasticState<Dim>> plastic_state{"plasticity"};
/// The history of a hencky_j2 point (HenckyJ2State: G^p, xi, plastic work).
template <int Dim>
inline constexpr FieldKey<HenckyJ2State<Dim>> hencky_j2_state{"hencky_j2"};
/// The mixed volume Theta of the three-field form (ref. 003 eqs. 11, 88e), per particle: only the implicit scheme
/// adds it; hencky_j2's stored energy then uses U(Theta) instead of U(J).
inline constexpr FieldKey<Real> mixed_volume{"mixed_volume"};

}  // namespace mpm::plasticity::keys
