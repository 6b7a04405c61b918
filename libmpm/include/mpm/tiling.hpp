#pragma once
/// \file tiling.hpp
/// The fixed global tiling of the grid that distributed runs are cut along (issue 18, docs/distributed.md §2),
/// and its model: which rank owns which tile, the particles and cost per rank, and the ghost nodes and halo
/// bytes a step exchanges. The tiling depends on the grid and the shape function only, never on the number of
/// ranks, so that a node's contributions can be combined in one order whatever the owners of its tiles.
///
/// Tiles are boxes of `tile_cells` cells per axis (the last tile of an axis may be shorter). A tile is at least
/// as wide as a particle's reach (`Shape::slab_cells`, the slab thickness of the threaded scatter): two tiles of
/// the same colour (the parity of their tile coordinates, 2^d colours) are one tile apart, so their particles
/// never reach the same node and all tiles of a colour can scatter at once. Node ownership: a node belongs to
/// the tile whose cell range starts at or below it on every axis (the node between two tiles to the upper one,
/// the grid's last node to the last tile).
///
/// Used today by `mpm check --ranks N` (what a run on N ranks would hold, before that run exists).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mpm/grid.hpp"

namespace mpm {

/// Cells per tile edge unless the shape function's reach needs more: 8 keeps the ghost layer of a tile (one or
/// two nodes deep) small against its 8^d cells, and gives a 256^3 grid 32,768 tiles to balance over ranks.
constexpr int default_tile_cells = 8;

template <int Dim>
struct Tiling {
  int tile_cells = default_tile_cells;  ///< cells per tile edge, every axis
  std::array<int, Dim> cells{};         ///< grid cells per axis
  std::array<int, Dim> tiles{};         ///< tiles per axis, ceil(cells / tile_cells)

  Index tile_count() const {
    Index n = 1;
    for (int d = 0; d < Dim; ++d) n *= tiles[d];
    return n;
  }
  /// Tile coordinate of cell `c` on an axis.
  int tile_of_cell(int c) const { return c / tile_cells; }
  /// Tile coordinate owning node `n` on axis `d` (the last node belongs to the last tile).
  int tile_of_node(int d, int n) const { return n / tile_cells < tiles[d] ? n / tile_cells : tiles[d] - 1; }
  /// Linear index of a tile, first axis fastest (like nodes and cells).
  Index index(const std::array<int, Dim>& t) const {
    Index i = 0, stride = 1;
    for (int d = 0; d < Dim; ++d) {
      i += stride * t[d];
      stride *= tiles[d];
    }
    return i;
  }
  std::array<int, Dim> coordinates(Index i) const {
    std::array<int, Dim> t{};
    for (int d = 0; d < Dim; ++d) {
      t[d] = static_cast<int>(i % tiles[d]);
      i /= tiles[d];
    }
    return t;
  }
  /// The colour of a tile: bit d is the parity of its coordinate d (2^d colours, none adjacent to its own).
  static int colour(const std::array<int, Dim>& t) {
    int c = 0;
    for (int d = 0; d < Dim; ++d) c |= (t[d] & 1) << d;
    return c;
  }
};

/// The tiling of `g` for a shape function whose scatter needs slabs `slab_cells` thick.
template <int Dim>
Tiling<Dim> make_tiling(const GridGeometry<Dim>& g, int slab_cells);

/// Nodes a particle in cell c can reach on an axis, [c - below, c + above], for a shape function with `support`
/// nodes per axis (review §3): linear 0..1, quadratic and cubic B-splines and GIMP c-1..c+2, CPDI of reach R
/// c-R..c+R+1. The cubic B-spline's face functions reach nodes 0..3 from cell 0 (and the mirror at the upper
/// face): still inside the face's tile, so the ghost count does not change.
struct CellReach {
  int below = 0, above = 1;
};
CellReach cell_reach(int support);

/// Doubles a ghost node carries each way per step: the partial sums a non-owner sends and the totals it gets
/// back, for the nodal fields the scheme scatters (mass, momentum, force; MUSL's re-mapped momentum too).
int halo_doubles_per_node(int dim, const std::string& scheme);

/// What a run on `ranks` ranks would hold: the tiles in Morton order cut into at most `ranks` contiguous runs whose
/// largest cost is the least possible (cost of a tile: particles x stencil nodes + its nodes if a particle reaches
/// it); ranks past the last run own no tile.
struct RankShare {
  Index particles = 0;
  Index tiles = 0;        ///< tiles owned
  Index ghost_nodes = 0;  ///< nodes of other ranks' tiles this rank's particles reach
  double cost = 0;
};

struct DecompositionModel {
  Index tiles = 0;           ///< all tiles of the grid
  Index occupied_tiles = 0;  ///< tiles holding a particle: the most ranks that all get work
  Index active_tiles = 0;    ///< tiles holding a particle or in reach of one (allocated in a sparse grid)
  std::vector<int> rank_of_tile;
  std::vector<RankShare> ranks;
  Index ghost_nodes() const;
  double imbalance() const;  ///< most loaded rank's cost over the mean
};

/// The model of a run on `ranks` ranks (1 <= ranks <= tiling.tile_count()) whose particles sit in `cells` (one
/// linear cell index per particle, first axis fastest). `support`: the shape function's nodes per axis.
template <int Dim>
DecompositionModel model_decomposition(const Tiling<Dim>& tiling, const std::vector<Index>& cells, int support,
                                       int ranks);

/// Morton (Z-order) key of tile coordinates: the bits of the coordinates interleaved, first axis lowest.
template <int Dim>
std::uint64_t morton_key(const std::array<int, Dim>& t);

}  // namespace mpm
