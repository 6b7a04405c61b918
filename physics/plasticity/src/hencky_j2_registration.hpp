#pragma once
// Registration of the material model hencky_j2 (hencky_j2_registration.cpp), called once by register_module().
#include <memory>

#include "mpm/materials/material.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::plasticity::detail {

/// Adds hencky_j2 to the material catalog (parameters) and the material factory (builders in 1D, 2D, 3D).
void register_hencky_j2();

/// The builder behind the factory.
template <int Dim>
std::unique_ptr<Material<Dim>> make_hencky_j2(const MaterialDescription& description);

}  // namespace mpm::plasticity::detail
