#pragma once
/// \file material_factory.hpp
/// Builds a Material<Dim> from a validated scene description, by model key.

#include <memory>

#include "mpm/material.hpp"
#include "mpm/scene.hpp"

namespace mpm {

/// Throws std::invalid_argument for an unknown model (the scene loader has normally caught it).
template <int Dim>
std::unique_ptr<Material<Dim>> make_material(const MaterialDescription& description);

}  // namespace mpm
