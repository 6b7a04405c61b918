#pragma once
/// \file slab_binning.hpp
/// Race-free, deterministic particle-to-grid scatter without locks. The grid is cut along its last axis
/// into slabs `Shape::slab_cells` cells thick; a particle belongs to the slab of its cell. Two slabs of
/// the same colour (even or odd) are never adjacent, and a slab is thick enough that particles of two
/// same-coloured slabs never reach the same node. So all even slabs scatter in parallel, then all odd
/// ones. Inside a slab particles are visited in storage order, so every node receives its contributions in
/// an order that does not depend on the thread count: results are bit-identical for any --threads. The
/// storage order is set by order_by_cell before the first step and every `solver.sort_interval` steps (TLMPM:
/// once): by (cell, id), a function of the particles' positions at that step and their ids, not of where they
/// sat in memory before, so results do not depend on the order of the input either (docs/distributed.md §1).

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "mpm/particle_set.hpp"
#include "mpm/slab_halo.hpp"

namespace mpm {

struct SlabBins {
  int slab_cells = 1;
  int slab_count = 0;
  std::vector<Index> offsets;  ///< slab s holds order[offsets[s] .. offsets[s+1])
  std::vector<Index> order;    ///< particle indices grouped by slab, in storage order inside a slab
  Index outside = -1;          ///< first particle found outside the grid box (or non-finite), -1 if none
  std::vector<int> slab_of;    ///< scratch: slab of each particle (kept to avoid reallocating every step)
  std::vector<Index> cursor;   ///< scratch
  /// Distributed run: the ghost-node exchange after each colour round (slab_halo.hpp); null in one process.
  const SlabHalo* halo = nullptr;
};

/// The linear index of the cell holding x (first axis fastest, so that the cells of a slab of the last axis
/// are contiguous), each axis clamped into the grid; non-finite coordinates count as cell 0 of their axis.
template <int Dim>
Index cell_index(const VecU<Dim>& x, const GridGeometry<Dim>& g) {
  Index c = 0, stride = 1;
  for (int d = 0; d < Dim; ++d) {
    const Real xi = (x[d] - g.origin[d]) * g.inv_h[d];
    const int k = std::isfinite(xi) ? std::clamp(static_cast<int>(xi), 0, g.cells(d) - 1) : 0;
    c += stride * k;
    stride *= g.cells(d);
  }
  return c;
}

/// The scatter key of a particle: cell, then id. Unique while ids are (they are per body).
inline std::uint64_t scatter_key(Index cell, std::uint32_t id) { return (static_cast<std::uint64_t>(cell) << 32) | id; }

/// Groups the particles of `p` by slab, in storage order inside a slab: an O(N) stable counting sort;
/// flags particles outside the grid box. The storage order is (cell, id) at the last sort
/// (order_by_cell, every `solver.sort_interval` steps, before the first step, and once for TLMPM).
template <int Dim>
void bin_by_slab(const ParticleSet<Dim>& p, const GridGeometry<Dim>& g, int slab_cells, SlabBins& bins) {
  constexpr int axis = Dim - 1;
  const int cells = g.cells(axis);
  bins.slab_cells = slab_cells;
  bins.slab_count = (cells + slab_cells - 1) / slab_cells;
  bins.outside = -1;
  const Index n = p.size();
  const Vec<Dim> lower = g.origin, upper = g.upper();
  std::vector<int>& slab = bins.slab_of;
  slab.resize(n);
  bins.offsets.assign(bins.slab_count + 1, 0);
  for (Index i = 0; i < n; ++i) {
    const auto& x = p.x[i];
    bool inside = true;
    for (int d = 0; d < Dim; ++d) inside = inside && x[d] >= lower[d] && x[d] <= upper[d];  // false for NaN
    if (!inside && bins.outside < 0) bins.outside = i;
    const Real xi = inside ? (x[axis] - g.origin[axis]) * g.inv_h[axis] : 0;
    const int cell = std::clamp(static_cast<int>(xi), 0, cells - 1);
    slab[i] = cell / slab_cells;
    ++bins.offsets[slab[i] + 1];
  }
  for (int s = 0; s < bins.slab_count; ++s) bins.offsets[s + 1] += bins.offsets[s];
  bins.order.resize(n);
  bins.cursor.assign(bins.offsets.begin(), bins.offsets.end() - 1);
  for (Index i = 0; i < n; ++i) bins.order[bins.cursor[slab[i]]++] = i;
}

/// Calls body(indices, count) for every slab, even slabs in parallel first, then odd slabs. `written`: the nodal
/// arrays the body adds to; in a distributed run their ghost nodes are exchanged around each colour
/// (slab_halo.hpp): the slabs of a colour that write nodes another rank holds scatter first and their message
/// leaves while the others scatter. Slabs of one colour write disjoint nodes, so that order changes no bit.
template <class Body>
void for_each_slab_coloured(const SlabBins& bins, std::span<const HaloArray> written, Body&& body) {
  const auto scatter = [&](int s) {
    const Index begin = bins.offsets[s], end = bins.offsets[s + 1];
    if (end > begin) body(bins.order.data() + begin, end - begin);
  };
  const SlabHalo* halo = bins.halo;
  if (halo) halo->begin_scatter(written);
  for (int colour = 0; colour < 2; ++colour) {
    const int n = (bins.slab_count - colour + 1) / 2;
    if (!halo) {
      tbb::parallel_for(0, n, [&](int k) { scatter(2 * k + colour); });
      continue;
    }
    halo->before_round(colour);
    const std::vector<int>& boundary = halo->boundary_slabs(colour);
    tbb::parallel_for(0, static_cast<int>(boundary.size()), [&](int k) { scatter(boundary[k]); });
    halo->send(colour);
    tbb::parallel_for(0, n, [&](int k) {
      const int s = 2 * k + colour;
      if (std::find(boundary.begin(), boundary.end(), s) == boundary.end()) scatter(s);
    });
  }
  if (halo) halo->end_scatter();
}
template <class Body>
void for_each_slab_coloured(const SlabBins& bins, std::initializer_list<HaloArray> written, Body&& body) {
  for_each_slab_coloured(bins, std::span<const HaloArray>(written.begin(), written.size()), std::forward<Body>(body));
}

/// A scatter whose arrays have no halo yet (the modules that a distributed run refuses, Simulation::distribute).
template <class Body>
void for_each_slab_coloured(const SlabBins& bins, Body&& body) {
  if (bins.halo) throw std::logic_error("a scatter without ghost-node exchange ran in a distributed run");
  for_each_slab_coloured(bins, {}, std::forward<Body>(body));
}

/// Permutation that sorts particles by (cell, id), the scatter key: after it the storage order, and so the
/// scatter order inside a slab, depends on the particles' positions and ids only, whatever it was before.
/// A counting sort by cell, O(N + cells), stable (so the particles of a cell come in their previous storage
/// order, which is id order when they were sorted before and have not changed cells), then an insertion sort
/// of the ids inside each cell, which moves a particle only past the few of its own cell with a larger id; a
/// storage far from that order (a first sort of a shuffled input with many particles per cell) falls back to
/// a sort of the keys beyond 8 moves per particle.
template <int Dim>
std::vector<Index> order_by_cell(const ParticleSet<Dim>& p, const GridGeometry<Dim>& g) {
  const Index n = p.size();
  Index cell_count = 1;
  for (int d = 0; d < Dim; ++d) cell_count *= g.cells(d);
  std::vector<std::uint64_t> key(n), sorted(n);
  std::vector<Index> start(cell_count + 1, 0), order(n);
  for (Index i = 0; i < n; ++i) {
    const Index cell = cell_index<Dim>(p.x[i], g);
    key[i] = scatter_key(cell, p.id[i]);
    ++start[cell + 1];
  }
  for (Index c = 0; c < cell_count; ++c) start[c + 1] += start[c];
  for (Index i = 0; i < n; ++i) {
    const Index k = start[static_cast<Index>(key[i] >> 32)]++;
    order[k] = i;
    sorted[k] = key[i];
  }
  Index moves = 0;
  for (Index k = 1; k < n; ++k) {
    if (sorted[k - 1] <= sorted[k]) continue;
    const Index i = order[k];
    const std::uint64_t ki = sorted[k];
    Index j = k;
    for (; j > 0 && sorted[j - 1] > ki; --j) {
      order[j] = order[j - 1];
      sorted[j] = sorted[j - 1];
    }
    order[j] = i;
    sorted[j] = ki;
    moves += k - j;
    if (moves > 8 * n) {  // equal keys (repeated ids) keep their order in both sorts
      std::vector<Index> all(static_cast<std::size_t>(n));
      for (Index m = 0; m < n; ++m) all[m] = m;
      std::stable_sort(all.begin(), all.end(), [&](Index a, Index b) { return key[a] < key[b]; });
      return all;
    }
  }
  return order;
}

}  // namespace mpm
