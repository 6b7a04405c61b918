#pragma once
/// \file register.hpp
/// Registration of the plasticity module: the material models johnson_cook, j2_plasticity and hencky_j2 with their
/// parameters (for the scene loader) and builders (for the simulation builder). Called by the generated
/// mpm::app::register_modules() when the module is compiled in (CMake option MPM_WITH_PLASTICITY).

#include <memory>

#include "mpm/materials/material.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::plasticity {

/// Adds johnson_cook, j2_plasticity and hencky_j2 to the material catalog and factory (idempotent).
void register_module();

/// The builders behind the registry (also used directly by tests).
template <int Dim>
std::unique_ptr<Material<Dim>> make_johnson_cook(const MaterialDescription& description);
template <int Dim>
std::unique_ptr<Material<Dim>> make_j2_plasticity(const MaterialDescription& description);

}  // namespace mpm::plasticity
