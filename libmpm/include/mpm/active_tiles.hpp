#pragma once
/// \file active_tiles.hpp
/// Sparse tiles in one process (issue 18): the grid kernels of a step visit only the nodes that the particles of the
/// occupied tiles reach, so a grid much larger than its bodies (a Taylor anvil's free flight, a dam break's empty
/// tank) costs its particles' nodes in the grid update, not its bounding box. The node arrays stay allocated whole.
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

#include "mpm/node_runs.hpp"
#include "mpm/tile_binning.hpp"
#include "mpm/tile_halo.hpp"

namespace mpm {

/// The nodes the particles of the marked tiles (`marked[t]` != 0, TileGrid numbering) can reach, as ascending
/// runs: per row of nodes along the first axis, the union of the reach of the marked tiles whose reach holds the row.
void reached_node_runs(const TileGrid& grid, std::span<const std::uint8_t> marked, std::vector<NodeRun>& runs);

/// The tiles holding particles at this step and the previous one, and the nodes their particles reach.
class ActiveTiles {
 public:
  /// Marks the tiles holding a particle of any of `bins` (binned on `grid`'s tiles) and returns the nodes that the
  /// particles of this step's and the previous step's marked tiles reach. The first step, and any step whose tiling
  /// differs from the previous one's, returns every node (the previous marks say nothing then).
  NodeRuns update(const TileGrid& grid, std::span<const TileBins* const> bins);
  /// The nodes the last update returned.
  NodeRuns nodes() const { return dense_ ? NodeRuns{} : NodeRuns::of(runs_); }
  /// Forgets the previous marks: the next update returns every node (after the grid was written by other means: a
  /// restored snapshot).
  void forget() { known_ = false; }

 private:
  TileGrid grid_;
  bool known_ = false;  ///< whether `now_` holds the marks of the previous update, on grid_
  bool dense_ = true;
  std::vector<std::uint8_t> now_, either_;
  std::vector<NodeRun> runs_;
};

}  // namespace mpm
