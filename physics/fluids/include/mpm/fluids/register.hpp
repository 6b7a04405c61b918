#pragma once
/// \file register.hpp
/// Registration of the fluids module: the material models newtonian_fluid (Tait EOS) and ideal_gas.
/// Called by the generated mpm::app::register_modules() when compiled in (CMake option MPM_WITH_FLUIDS).

#include <memory>

#include "mpm/materials/material.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::fluids {

void register_module();

template <int Dim>
std::unique_ptr<Material<Dim>> make_newtonian_fluid(const MaterialDescription& description);
template <int Dim>
std::unique_ptr<Material<Dim>> make_incompressible_fluid(const MaterialDescription& description);
template <int Dim>
std::unique_ptr<Material<Dim>> make_ideal_gas(const MaterialDescription& description);

}  // namespace mpm::fluids
