#pragma once
/// \file tile_grid.hpp
/// The tiles of the threaded scatter (tile_binning.hpp): blocks of cells with 2^d colours, numbered first axis
/// fastest, the same on every rank of a distributed run (the unit ranks own, parallel/tile_halo.hpp) and the unit the
/// sparse grid marks (active_tiles.hpp); docs/distributed.md §1-2.

#include <algorithm>
#include <array>
#include <utility>

#include "mpm/core/types.hpp"
#include "mpm/grid/grid.hpp"

namespace mpm {

/// The tiles of the threaded scatter (tile_binning.hpp) as a distributed run sees them: the same on every rank, a
/// function of the grid and the shape function only. Tile t has coordinates (t mod tiles_0, ...), first axis fastest
/// (bin_by_tile's numbering); its colour's bit d is the parity of coordinate d.
struct TileGrid {
  int dim = 1;
  std::array<int, 3> tiles{1, 1, 1};       ///< tiles per axis
  std::array<int, 3> tile_cells{1, 1, 1};  ///< cells per tile edge (last axis: the slab, Shape::slab_cells)
  std::array<int, 3> cells{1, 1, 1};       ///< grid cells per axis
  std::array<int, 3> nodes{1, 1, 1};       ///< grid nodes per axis
  int reach_below = 0;                     ///< node layers a tile's particles reach below its first cell
  int reach_above = 1;                     ///< ... and above its last (Shape::slab_reach_below / above)

  Index tile_count() const { return Index{tiles[0]} * tiles[1] * tiles[2]; }
  Index node_count() const { return Index{nodes[0]} * nodes[1] * nodes[2]; }
  std::array<int, 3> coordinates(Index t) const {
    return {static_cast<int>(t % tiles[0]), static_cast<int>(t / tiles[0] % tiles[1]),
            static_cast<int>(t / (Index{tiles[0]} * tiles[1]))};
  }
  Index index(const std::array<int, 3>& c) const { return c[0] + Index{tiles[0]} * (c[1] + Index{tiles[1]} * c[2]); }
  int colour(Index t) const {
    const auto c = coordinates(t);
    return (c[0] & 1) | (c[1] & 1) << 1 | (c[2] & 1) << 2;
  }
  int colours() const { return 1 << dim; }
  /// Nodes of axis d that the particles of tile coordinate c can reach, [first, last].
  std::pair<int, int> reach(int d, int c) const;
  /// The tile coordinate on axis d whose cells start at or below node k (the grid's last node: the last tile), the
  /// owner of the node on that axis.
  int tile_of_node(int d, int k) const { return std::min(k / tile_cells[d], tiles[d] - 1); }
  /// The tile coordinates on axis d whose particles can reach node k, [first, last]: the tiles c with
  /// c w - below <= k <= (c + 1) w - 1 + above.
  std::pair<int, int> writers(int d, int k) const {
    const int w = tile_cells[d];
    return {k - reach_above >= 0 ? (k - reach_above) / w : 0, std::min(tiles[d] - 1, (k + reach_below) / w)};
  }
  bool operator==(const TileGrid&) const = default;
};

/// The tiles of the scatter on grid `g` for a shape function of slab `slab_cells` and reach (below, above).
template <int Dim>
TileGrid make_tile_grid(const GridGeometry<Dim>& g, int slab_cells, int below, int above);

}  // namespace mpm
