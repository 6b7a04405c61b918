#pragma once
/// \file node_runs.hpp
/// The nodes a step's grid kernels visit, as ascending runs of node indices. A grid
/// kernel (reset, velocity update, MUSL re-map, contact sums) visits only the nodes a particle can reach, so an empty
/// region of the grid costs nothing in the grid update, whatever the bounding box:
/// - one process: the nodes the particles of the occupied tiles reach, this step's and the previous step's
///   (ActiveTiles, active_tiles.hpp);
/// - a distributed run: the nodes the rank's tiles reach (HaloPlan::held), the nodes it holds.
/// Without runs (NodeRuns{}), every node: TLMPM, the implicit scheme and unit tests.

#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include "mpm/core/parallel_chunks.hpp"
#include "mpm/core/types.hpp"

namespace mpm {

/// Nodes [first, end).
using NodeRun = std::pair<Index, Index>;

/// A set of grid nodes as ascending, disjoint runs; `all` (the default): every node of the grid.
struct NodeRuns {
  std::span<const NodeRun> runs{};
  bool all = true;

  static NodeRuns of(const std::vector<NodeRun>& runs) { return {std::span<const NodeRun>(runs), false}; }
  /// Nodes in the set on a grid of `nodes` nodes.
  Index count(Index nodes) const {
    if (all) return nodes;
    Index n = 0;
    for (const auto& [first, end] : runs) n += std::max<Index>(0, std::min(end, nodes) - first);
    return n;
  }
};

/// Calls block(begin, end) for blocks of the nodes of `set` below `nodes`, in parallel; each block lies inside one run
/// and holds about `grain` nodes or fewer. For kernels that treat each node on its own (the order of the calls is
/// free).
template <class Block>
void for_each_node_block(Index nodes, NodeRuns set, Index grain, Block&& block) {
  if (set.all) {
    parallel_chunks(Index{0}, nodes, static_cast<std::size_t>(grain), block);
    return;
  }
  parallel_chunks(std::size_t{0}, set.runs.size(), 1, [&](std::size_t run_begin, std::size_t run_end) {
    for (std::size_t k = run_begin; k != run_end; ++k) {
      const Index first = set.runs[k].first, end = std::min(set.runs[k].second, nodes);
      if (end - first <= grain) {
        if (end > first) block(first, end);
        continue;
      }
      parallel_chunks(first, end, static_cast<std::size_t>(grain), block);
    }
  });
}

/// Calls visit(n) for every node of `set` below `nodes`, in ascending order, on the calling thread (passes whose
/// order matters: a list of contact candidates).
template <class Visit>
void for_each_node_in_order(Index nodes, NodeRuns set, Visit&& visit) {
  if (set.all) {
    for (Index n = 0; n < nodes; ++n) visit(n);
    return;
  }
  for (const auto& [first, end] : set.runs)
    for (Index n = first, stop = std::min(end, nodes); n < stop; ++n) visit(n);
}

/// Calls visit(j) for each position j of the ascending node list `list` (a face's nodes) whose node is in `set`, in
/// ascending order: a face condition then writes only the nodes the step's kernels visit, and the rest of the face
/// costs neither time nor memory (reserved_pages.hpp).
template <class Visit>
void for_each_listed_node(std::span<const Index> list, NodeRuns set, Visit&& visit) {
  if (set.all) {
    for (std::size_t j = 0; j < list.size(); ++j) visit(j);
    return;
  }
  auto at = list.begin();
  for (const auto& [first, end] : set.runs) {
    at = std::lower_bound(at, list.end(), first);
    for (; at != list.end() && *at < end; ++at) visit(static_cast<std::size_t>(at - list.begin()));
    if (at == list.end()) return;
  }
}

}  // namespace mpm
