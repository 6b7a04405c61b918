#pragma once
/// \file primitive_filler.hpp
/// The lattice fill is the core's (mpm/body_shape/lattice_fill.hpp): every grid cell divided into ppc_x x ppc_y x
/// ppc_z sub-cells, a particle at each sub-cell centre inside the region.

#include "mpm/body_shape/lattice_fill.hpp"
#include "mpm/geometry/region.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::geometry {

using mpm::fill_region;
using mpm::ParticleSeeds;

}  // namespace mpm::geometry
