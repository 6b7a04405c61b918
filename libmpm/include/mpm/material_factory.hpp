#pragma once
/// \file material_factory.hpp
/// Builds a Material<Dim> from a validated scene description, by model key.

#include <memory>
#include <string>

#include "mpm/material.hpp"
#include "mpm/scene.hpp"

namespace mpm {

/// Throws std::invalid_argument for an unknown model (the scene loader has normally caught it).
template <int Dim>
std::unique_ptr<Material<Dim>> make_material(const MaterialDescription& description);

/// Builds a model of an optional module from its validated description.
template <int Dim>
using MaterialMaker = std::unique_ptr<Material<Dim>> (*)(const MaterialDescription&);
/// Registers the builders of an optional module's model for 1D, 2D and 3D (called once per model by the
/// module's registration function, with register_material_model() for its parameters).
void register_material_factory(const std::string& model, MaterialMaker<1> make_1d, MaterialMaker<2> make_2d,
                               MaterialMaker<3> make_3d);

}  // namespace mpm
