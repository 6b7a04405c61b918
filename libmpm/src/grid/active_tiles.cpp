#include "mpm/grid/active_tiles.hpp"

#include <algorithm>
#include <stdexcept>

namespace mpm {

void reached_node_runs(const TileGrid& grid, std::span<const std::uint8_t> marked, std::vector<NodeRun>& runs) {
  if (static_cast<Index>(marked.size()) != grid.tile_count())
    throw std::invalid_argument("reached_node_runs: one mark per tile");
  runs.clear();
  // Per row of tiles along the first axis: the merged node intervals [first, last] its marked tiles reach on it.
  const Index rows = Index{grid.tiles[1]} * grid.tiles[2];
  std::vector<Index> start(static_cast<std::size_t>(rows) + 1, 0);
  std::vector<std::pair<int, int>> reach;
  for (Index row = 0; row < rows; ++row) {
    const std::size_t row_start = reach.size();
    for (int t0 = 0; t0 < grid.tiles[0]; ++t0) {
      if (!marked[static_cast<std::size_t>(row * grid.tiles[0] + t0)]) continue;
      const auto [first, last] = grid.reach(0, t0);
      if (reach.size() > row_start && reach.back().second + 1 >= first)
        reach.back().second = std::max(reach.back().second, last);
      else
        reach.emplace_back(first, last);
    }
    start[static_cast<std::size_t>(row) + 1] = static_cast<Index>(reach.size());
  }
  // Per row of nodes: the union of the intervals of the tile rows whose reach holds it (at most 2^(d-1) of them when
  // a tile is at least as wide as the reach), shifted to the row's first node.
  std::vector<std::pair<int, int>> row_reach;
  std::array<int, 3> k{0, 0, 0};
  for (k[2] = 0; k[2] < grid.nodes[2]; ++k[2]) {
    const auto [f2, l2] = grid.dim > 2 ? grid.writers(2, k[2]) : std::pair<int, int>{0, 0};
    for (k[1] = 0; k[1] < grid.nodes[1]; ++k[1]) {
      const auto [f1, l1] = grid.dim > 1 ? grid.writers(1, k[1]) : std::pair<int, int>{0, 0};
      row_reach.clear();
      for (int t2 = f2; t2 <= l2; ++t2)
        for (int t1 = f1; t1 <= l1; ++t1) {
          const Index row = t1 + Index{grid.tiles[1]} * t2;
          row_reach.insert(row_reach.end(), reach.begin() + start[static_cast<std::size_t>(row)],
                           reach.begin() + start[static_cast<std::size_t>(row) + 1]);
        }
      if (row_reach.empty()) continue;
      std::sort(row_reach.begin(), row_reach.end());
      const Index base = Index{grid.nodes[0]} * (k[1] + Index{grid.nodes[1]} * k[2]);
      for (const auto& [first, last] : row_reach) {
        const Index a = base + first, b = base + last + 1;
        if (!runs.empty() && runs.back().second >= a)
          runs.back().second = std::max(runs.back().second, b);
        else
          runs.emplace_back(a, b);
      }
    }
  }
}

namespace {

/// The maximal stretches of [0, nodes) outside `runs` (ascending, disjoint) that hold a node of `before`.
void stretches_left(const std::vector<NodeRun>& runs, const std::vector<NodeRun>& before, Index nodes,
                    std::vector<NodeRun>& left) {
  left.clear();
  auto b = before.begin();
  Index gap_first = 0;
  for (std::size_t k = 0; k <= runs.size(); ++k) {
    const Index gap_end = k < runs.size() ? runs[k].first : nodes;
    while (b != before.end() && b->second <= gap_first) ++b;  // runs of `before` wholly below the gap
    if (gap_end > gap_first && b != before.end() && b->first < gap_end) left.emplace_back(gap_first, gap_end);
    if (k < runs.size()) gap_first = runs[k].second;
  }
}

}  // namespace

NodeRuns ActiveTiles::update(const TileGrid& grid, std::span<const TileBins* const> bins) {
  const auto tiles = static_cast<std::size_t>(grid.tile_count());
  const bool same_tiling = known_ && (zero_ || grid == grid_);
  if (!same_tiling || zero_) now_.assign(tiles, 0);
  either_ = now_;  // the previous step's marks (zero when unknown)
  std::fill(now_.begin(), now_.end(), 0);
  for (const TileBins* b : bins) {
    if (static_cast<std::size_t>(b->tile_count()) != tiles)
      throw std::logic_error("ActiveTiles: the bins and the tile grid tile the grid differently");
    for (std::size_t t = 0; t < tiles; ++t)
      if (b->offsets[t + 1] > b->offsets[t]) now_[t] = 1;
  }
  if (!always_.empty()) {
    if (always_.size() != tiles) throw std::logic_error("ActiveTiles: the always-marked tiles are of another grid");
    for (std::size_t t = 0; t < tiles; ++t) now_[t] |= always_[t];
  }
  for (std::size_t t = 0; t < tiles; ++t) either_[t] |= now_[t];
  // What the kernels visited at the previous step: every node after a dense step, nothing on a zero grid.
  previous_.clear();
  if (known_ && !zero_) {
    if (dense_)
      previous_.emplace_back(0, grid_.node_count());
    else
      previous_.swap(runs_);
  }
  grid_ = grid;
  dense_ = !same_tiling;
  known_ = true;
  zero_ = false;
  left_.clear();
  if (!dense_) {
    reached_node_runs(grid, either_, runs_);
    stretches_left(runs_, previous_, grid.node_count(), left_);
  }
  return nodes();
}

}  // namespace mpm
