#pragma once
/// \file active_tiles.hpp
/// Sparse tiles in one process: the grid kernels of a step visit only the nodes that the particles of the
/// occupied tiles reach, so a grid much larger than its bodies (a Taylor anvil's free flight, a dam break's empty
/// tank) costs its particles' nodes in the grid update, not its bounding box. The node arrays are reserved address
/// space (reserved_pages.hpp): pages no kernel writes cost no memory, and the pages of the stretches the particles
/// left are given back (left()).
///
/// **Why this step's and the previous step's tiles.** A node the particles leave keeps its mass and velocity until
/// something clears it; a dense grid clears it at the next reset and gives it zero velocity at the next update. So
/// a step visits the nodes of the tiles occupied now *or* at the previous step: every node that held anything gets
/// the dense treatment once more, and every node outside that set is already what the dense grid would hold (zero
/// mass, momentum and force; zero velocity but for the face conditions, which write their nodes in both). Particles,
/// grid output and energies then have the bits of the dense grid (test SparseGrid.*).

#include <cstdint>
#include <span>
#include <vector>

#include "mpm/grid/node_runs.hpp"
#include "mpm/grid/tile_binning.hpp"
#include "mpm/grid/tile_grid.hpp"

namespace mpm {

/// The nodes the particles of the marked tiles (`marked[t]` != 0, TileGrid numbering) can reach, as ascending
/// runs: per row of nodes along the first axis, the union of the reach of the marked tiles whose reach holds the row.
void reached_node_runs(const TileGrid& grid, std::span<const std::uint8_t> marked, std::vector<NodeRun>& runs);

/// The tiles holding particles at this step and the previous one, and the nodes their particles reach.
class ActiveTiles {
 public:
  /// Marks the tiles holding a particle of any of `bins` (binned on `grid`'s tiles) and returns the nodes that the
  /// particles of this step's and the previous step's marked tiles reach. A step whose tiling differs from the previous
  /// one's, and the first after forget(), returns every node (the previous marks say nothing then); the first step
  /// of a new simulation knows that no tile was marked before (its grid is zero).
  NodeRuns update(const TileGrid& grid, std::span<const TileBins* const> bins);
  /// Tiles marked at every update besides the occupied ones (one mark per tile of the next update's grid, or empty):
  /// a distributed run's tiles of this rank that write shared nodes (TileHalo::own_shared_tiles), whose nodes the
  /// exchanges write and other ranks' particles reach. The span must live until the next update.
  void always_mark(std::span<const std::uint8_t> marks) { always_ = marks; }
  /// The nodes the last update returned.
  NodeRuns nodes() const { return dense_ ? NodeRuns{} : NodeRuns::of(runs_); }
  /// The stretches of nodes the last update left: maximal runs between the nodes it returned (before the first, after
  /// the last) that hold a node the update before returned. No particle reaches them now and the kernels visit them
  /// no more; what they hold is zero or no longer read, so their whole pages can go back to the system
  /// (release_nodes in grid.hpp). Empty after a dense update.
  std::span<const NodeRun> left() const { return left_; }
  /// Forgets the previous marks: the next update returns every node (after the grid was written by other means: a
  /// restored snapshot, a run on the dense grid).
  void forget() {
    known_ = false;
    zero_ = false;
  }
  /// The grid was zeroed (Grid::clear): the next update knows that no tile was marked before, as on a new grid.
  void zeroed() {
    known_ = true;
    zero_ = true;
  }

 private:
  TileGrid grid_;
  bool known_ = true;  ///< whether `now_` holds the marks of the previous update, on grid_ (or zero_)
  bool zero_ = true;   ///< the grid was never written (a new simulation's zero-filled arrays): no tile marked before
  bool dense_ = true;
  std::vector<std::uint8_t> now_, either_;
  std::span<const std::uint8_t> always_;
  std::vector<NodeRun> runs_, previous_, left_;
};

}  // namespace mpm
