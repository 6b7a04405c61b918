#pragma once
/// \file scatter_exchange.hpp
/// What the threaded scatter (tile_binning.hpp, for_each_tile_coloured) asks of a distributed run's ghost-node
/// exchange, so that the kernels know no MPI: the tiles this rank scatters per colour (those writing nodes sent after
/// the colour first) and the four moments of an exchange. One implementation, parallel/tile_halo.hpp (TileHalo);
/// a run in one process has none.

#include <cstddef>
#include <span>
#include <vector>

#include "mpm/core/types.hpp"

namespace mpm {

/// A nodal array a scatter writes: `bytes_per_node` bytes per node, node n at base + n * bytes_per_node.
struct HaloArray {
  std::byte* base = nullptr;
  std::size_t bytes_per_node = 0;
  template <class T, class Alloc>
  static HaloArray of(std::vector<T, Alloc>& nodes) {
    return {reinterpret_cast<std::byte*>(nodes.data()), sizeof(T)};
  }
};

/// The exchange of the ghost nodes of one scatter, as for_each_tile_coloured drives it:
///   begin_scatter(arrays)   posts every receive of the scatter;
///   before_round(colour)    applies, in colour order, what the earlier colours' owners sent;
///   (the boundary tiles of the colour scatter)
///   send(colour)            starts this colour's messages;
///   (the inner tiles of the colour scatter: they write no node sent after this colour)
///   end_scatter()           applies the rest (totals) and waits for the sends.
class ScatterExchange {
 public:
  virtual ~ScatterExchange() = default;
  /// Tiles of the grid (the same tiling as the bins').
  virtual Index tile_count() const = 0;
  /// This rank's tiles of `colour` that write a node it sends after that colour, and its other tiles of the colour.
  virtual const std::vector<Index>& boundary_tiles(int colour) const = 0;
  virtual const std::vector<Index>& inner_tiles(int colour) const = 0;
  virtual void begin_scatter(std::span<const HaloArray> arrays) const = 0;
  virtual void before_round(int colour) const = 0;
  virtual void send(int colour) const = 0;
  virtual void end_scatter() const = 0;
};

}  // namespace mpm
