#pragma once
/// \file output_fields.hpp
/// The output fields of the plasticity module: members of PlasticState, one value per particle, 0 in
/// bodies without plasticity. This list is the one place a plastic output field is declared: the
/// registration (output table of mpm/output_fields.hpp) and PlasticBatch::append_output both read it.

#include <array>

#include "mpm/plasticity/elastoplastic.hpp"

namespace mpm::plasticity {

template <int Dim>
struct PlasticOutput {
  const char* name;
  const char* unit;
  const char* description;
  Real PlasticState<Dim>::*member;
};

template <int Dim>
inline constexpr std::array<PlasticOutput<Dim>, 4> plastic_outputs{{
    {"plastic_strain", "-", "equivalent plastic strain eps_p (-); 0 in bodies without plasticity",
     &PlasticState<Dim>::plastic_strain},
    {"plastic_strain_rate", "1/s", "plastic strain rate of the last step (1/s); 0 in bodies without plasticity",
     &PlasticState<Dim>::plastic_strain_rate},
    {"damage", "-", "Johnson-Cook damage D in [0, 1]; 0 without damage", &PlasticState<Dim>::damage},
    {"plastic_work", "J/m^3", "plastic work dissipated per reference volume (J/m^3); 0 in bodies without plasticity",
     &PlasticState<Dim>::plastic_work},
}};

/// Registers the fields above and the shared `temperature` (with its remedy: a material specific_heat).
void register_output_fields();

}  // namespace mpm::plasticity
