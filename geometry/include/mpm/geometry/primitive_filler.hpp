#pragma once
/// \file primitive_filler.hpp
/// The lattice fill (review §4.1): every grid cell is divided into ppc_x x ppc_y x ppc_z equal sub-cells
/// and a particle is put at each sub-cell centre that lies inside the region. The particles get the
/// sub-cell's volume, so they tile the filled cells exactly, or, when the region knows its exact volume
/// (a mesh, a polygon, an image), that volume divided by their number.

#include <array>
#include <vector>

#include "mpm/geometry/region.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::geometry {

template <int Dim>
struct ParticleSeeds {
  std::vector<Vec<Dim>> positions;  ///< m
  Real volume = 0;                  ///< m^3 (per unit out-of-plane size in 1D/2D), the same for all
  Real sub_cell_volume = 0;         ///< m^3, the volume of one lattice sub-cell (= volume unless scaled)
};

/// Sub-cell centres inside `region`, in the order of the cells (x fastest), then of the sub-cells.
template <int Dim>
ParticleSeeds<Dim> fill_region(const Region<Dim>& region, const GridGeometry<Dim>& grid,
                               const std::array<int, 3>& particles_per_cell);

}  // namespace mpm::geometry
