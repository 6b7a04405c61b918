#pragma once
/// \file slab_binning.hpp
/// Race-free, deterministic particle-to-grid scatter without locks. The grid is cut along its last axis
/// into slabs `Shape::slab_cells` cells thick; a particle belongs to the slab of its cell. Two slabs of
/// the same colour (even or odd) are never adjacent, and a slab is thick enough that particles of two
/// same-coloured slabs never reach the same node. So all even slabs scatter in parallel, then all odd
/// ones. Inside a slab particles are visited in the order of their key (cell, id): every node receives its
/// contributions in an order that depends neither on the thread count nor on where the particles sit in
/// memory (storage order changes with sorting, and with migration between MPI ranks), so results are
/// bit-identical for any --threads and any particle storage (docs/distributed.md §1).

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mpm/particle_set.hpp"

namespace mpm {

struct SlabBins {
  int slab_cells = 1;
  int slab_count = 0;
  std::vector<Index> offsets;  ///< slab s holds order[offsets[s] .. offsets[s+1])
  std::vector<Index> order;    ///< particle indices grouped by slab, by (cell, id) inside a slab
  Index outside = -1;          ///< first particle found outside the grid box (or non-finite), -1 if none
  std::vector<std::uint64_t> key;  ///< scratch: (cell << 32) | id of each particle (kept to avoid reallocating)
  std::vector<int> slab_of;        ///< scratch: slab of each particle
  std::vector<Index> cursor;       ///< scratch
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
inline std::uint64_t scatter_key(Index cell, std::uint32_t id) {
  return (static_cast<std::uint64_t>(cell) << 32) | id;
}

/// Sorts order[begin, end) by key[order[k]]: insertion sort, which costs one comparison per particle when
/// the particles are stored nearly in key order (they are sorted by the same key every
/// `solver.sort_interval` steps and move less than a cell per step), with a stable sort taking over when
/// the storage is far from that order (never sorted, or a long interval). Stable in both cases.
inline void sort_by_key(Index* order, Index count, const std::uint64_t* key) {
  Index moves = 0;
  const Index budget = 8 * count + 64;
  for (Index k = 1; k < count; ++k) {
    const Index i = order[k];
    const std::uint64_t ki = key[i];
    Index j = k;
    while (j > 0 && key[order[j - 1]] > ki) {
      order[j] = order[j - 1];
      --j;
    }
    order[j] = i;
    moves += k - j;
    if (moves > budget) {
      std::stable_sort(order, order + count, [key](Index a, Index b) { return key[a] < key[b]; });
      return;
    }
  }
}

/// Groups the particles of `p` by slab, by (cell, id) inside a slab. O(N) counting sort by slab, then a
/// sort inside each slab that is O(N) for nearly sorted storage; flags particles outside the grid box.
template <int Dim>
void bin_by_slab(const ParticleSet<Dim>& p, const GridGeometry<Dim>& g, int slab_cells, SlabBins& bins) {
  constexpr int axis = Dim - 1;
  const int cells = g.cells(axis);
  bins.slab_cells = slab_cells;
  bins.slab_count = (cells + slab_cells - 1) / slab_cells;
  bins.outside = -1;
  const Index n = p.size();
  const Vec<Dim> lower = g.origin, upper = g.upper();
  Index layer = 1;  // cells per layer of the last axis
  for (int d = 0; d < axis; ++d) layer *= g.cells(d);
  std::vector<int>& slab = bins.slab_of;
  slab.resize(n);
  bins.key.resize(n);
  bins.offsets.assign(bins.slab_count + 1, 0);
  for (Index i = 0; i < n; ++i) {
    const auto& x = p.x[i];
    bool inside = true;
    for (int d = 0; d < Dim; ++d) inside = inside && x[d] >= lower[d] && x[d] <= upper[d];  // false for NaN
    if (!inside && bins.outside < 0) bins.outside = i;
    const Index cell = cell_index<Dim>(x, g);
    bins.key[i] = scatter_key(cell, p.id[i]);
    slab[i] = static_cast<int>(cell / layer) / slab_cells;
    ++bins.offsets[slab[i] + 1];
  }
  for (int s = 0; s < bins.slab_count; ++s) bins.offsets[s + 1] += bins.offsets[s];
  bins.order.resize(n);
  bins.cursor.assign(bins.offsets.begin(), bins.offsets.end() - 1);
  for (Index i = 0; i < n; ++i) bins.order[bins.cursor[slab[i]]++] = i;
  tbb::parallel_for(0, bins.slab_count, [&](int s) {
    const Index begin = bins.offsets[s];
    sort_by_key(bins.order.data() + begin, bins.offsets[s + 1] - begin, bins.key.data());
  });
}

/// Calls body(indices, count) for every slab, even slabs in parallel first, then odd slabs.
template <class Body>
void for_each_slab_coloured(const SlabBins& bins, Body&& body) {
  for (int colour = 0; colour < 2; ++colour) {
    const int n = (bins.slab_count - colour + 1) / 2;
    tbb::parallel_for(0, n, [&](int k) {
      const int s = 2 * k + colour;
      const Index begin = bins.offsets[s], end = bins.offsets[s + 1];
      if (end > begin) body(bins.order.data() + begin, end - begin);
    });
  }
}

/// Permutation that sorts particles by (cell, id), the scatter key, for memory locality: after it the
/// storage order is the scatter order, whatever it was before. Counting sort by cell, O(N + cells), then
/// the ids inside each cell.
template <int Dim>
std::vector<Index> order_by_cell(const ParticleSet<Dim>& p, const GridGeometry<Dim>& g) {
  const Index n = p.size();
  Index cell_count = 1;
  for (int d = 0; d < Dim; ++d) cell_count *= g.cells(d);
  std::vector<Index> cell(n), offset(cell_count + 1, 0);
  std::vector<std::uint64_t> key(n);
  for (Index i = 0; i < n; ++i) {
    cell[i] = cell_index<Dim>(p.x[i], g);
    key[i] = scatter_key(cell[i], p.id[i]);
    ++offset[cell[i] + 1];
  }
  for (Index c = 0; c < cell_count; ++c) offset[c + 1] += offset[c];
  std::vector<Index> order(n);
  for (Index i = 0; i < n; ++i) order[offset[cell[i]]++] = i;
  sort_by_key(order.data(), n, key.data());
  return order;
}

}  // namespace mpm
