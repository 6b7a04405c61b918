#pragma once
/// \file body_shape/lattice_fill.hpp
/// The particles a body shape gives (`ParticleSeeds`) and the lattice fill most kinds use (review §4.1): every grid
/// cell is divided into ppc_x x ppc_y x ppc_z equal sub-cells and a particle is put at each sub-cell centre that lies
/// inside the region. The particles get the sub-cell's volume, so they tile the filled cells exactly, or, with
/// `volume: exact` and a region that knows its volume, that volume divided by their number.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "mpm/body_shape/region.hpp"
#include "mpm/grid/grid.hpp"

namespace mpm {

template <int Dim>
struct ParticleSeeds {
  std::vector<Vec<Dim>> positions;  ///< m
  Real volume = 0;                  ///< m^3 (per unit out-of-plane size in 1D/2D), the same for all
  Real sub_cell_volume = 0;         ///< m^3, the volume of one lattice sub-cell (= volume unless scaled)
  /// A kind that places its own particles with volumes of their own (a particle file): one per position, m^3;
  /// empty for the lattice (then `volume` is every particle's).
  std::vector<Real> volumes;
  /// What a particle file gives besides positions and volumes (absent: the body's velocity, density x volume, zero
  /// stress, ids in order).
  std::optional<std::vector<VecU<Dim>>> velocity;
  std::optional<std::vector<SymTensor<Dim>>> stress;
  std::optional<std::vector<Real>> mass;
  std::optional<std::vector<std::uint32_t>> id;
};

/// Sub-cell centres inside `region`, in the order of the cells (x fastest), then of the sub-cells. With `exact`
/// and a region that knows its volume the particles share it equally; otherwise each has the sub-cell's.
template <int Dim>
ParticleSeeds<Dim> fill_region(const Region<Dim>& region, const GridGeometry<Dim>& grid,
                               const std::array<int, 3>& particles_per_cell, bool exact = true);

}  // namespace mpm
