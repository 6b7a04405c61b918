#pragma once
/// \file particle_count.hpp
/// How many particles the lattice fill (primitive_filler.hpp) would make, without making them: the lattice
/// points of the region's bounding box are counted in closed form and a sample of them (about 32,768, evenly
/// strided on each axis) is tested for inside; the count is the inside fraction times the lattice points. When
/// the box holds no more lattice points than the sample, all are tested and the count is exact. The scene builder
/// checks a scene's memory against the machine's with it before filling anything (apps/src/memory_estimate.cpp).

#include <array>
#include <cstddef>

#include "mpm/geometry/region.hpp"
#include "mpm/grid/grid.hpp"

namespace mpm::geometry {

struct ParticleCount {
  double count = 0;         ///< particles (a double: a typo can ask for more than 2^63)
  double lattice = 0;       ///< lattice points in the bounding box (what fill_region visits at most)
  std::size_t sampled = 0;  ///< lattice points tested
  bool exact = false;       ///< every lattice point of the box was tested
};

/// Lattice points of the grid's fill lattice (`particles_per_cell` sub-cell centres per cell and axis) that lie in
/// `box`, in closed form.
template <int Dim>
double lattice_points_in(const Box<Dim>& box, const GridGeometry<Dim>& grid,
                         const std::array<int, 3>& particles_per_cell);

/// The particles fill_region(region, grid, particles_per_cell) would make, from `samples` lattice points at most.
template <int Dim>
ParticleCount count_particles(const Region<Dim>& region, const GridGeometry<Dim>& grid,
                              const std::array<int, 3>& particles_per_cell, std::size_t samples = 32768);

}  // namespace mpm::geometry
