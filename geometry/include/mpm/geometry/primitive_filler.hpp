#pragma once
/// \file primitive_filler.hpp
/// Fills a primitive shape (box, disk, sphere, cylinder) with particles: every grid cell is divided into
/// ppc_x x ppc_y x ppc_z equal sub-cells and a particle is put at each sub-cell centre that lies inside
/// the shape (review §4.1). Each particle gets the sub-cell's volume, so the particle volumes tile the
/// filled cells exactly.

#include <array>
#include <vector>

#include "mpm/grid.hpp"
#include "mpm/scene.hpp"

namespace mpm::geometry {

template <int Dim>
struct ParticleSeeds {
  std::vector<Vec<Dim>> positions;  ///< m
  Real volume = 0;                  ///< m^3 (per unit out-of-plane size in 1D/2D), the same for all
};

/// True when x lies in the shape (boundary included).
template <int Dim>
bool contains(const ShapeDescription& shape, const Vec<Dim>& x);

/// Sub-cell centres inside the shape, in the order of the cells (x fastest).
template <int Dim>
ParticleSeeds<Dim> fill_primitive(const ShapeDescription& shape, const GridGeometry<Dim>& grid,
                                  const std::array<int, 3>& particles_per_cell);

}  // namespace mpm::geometry
