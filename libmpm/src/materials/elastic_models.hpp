#pragma once
// The core's material models, registered like a module's (material_registry.cpp registers them first).
#include <vector>

#include "mpm/materials/material_registry.hpp"

namespace mpm {

/// linear_elastic and neo_hookean (review App. B.1-B.2).
std::vector<MaterialModel> elastic_material_models();

}  // namespace mpm
