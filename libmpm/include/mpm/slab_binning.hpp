#pragma once
/// \file slab_binning.hpp
/// Race-free, deterministic particle-to-grid scatter without locks. The grid is cut along its last axis
/// into slabs `Shape::slab_cells` cells thick; a particle belongs to the slab of its cell. Two slabs of
/// the same colour (even or odd) are never adjacent, and a slab is thick enough that particles of two
/// same-coloured slabs never reach the same node. So all even slabs scatter in parallel, then all odd
/// ones. Inside a slab particles are visited in index order, so every node receives its contributions
/// in an order that does not depend on the thread count: results are bit-identical for any --threads.

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mpm/particle_set.hpp"

namespace mpm {

struct SlabBins {
  int slab_cells = 1;
  int slab_count = 0;
  std::vector<Index> offsets;  ///< slab s holds order[offsets[s] .. offsets[s+1])
  std::vector<Index> order;    ///< particle indices grouped by slab, ascending inside a slab
  Index outside = -1;          ///< first particle found outside the grid box (or non-finite), -1 if none
  std::vector<int> slab_of;    ///< scratch: slab of each particle (kept to avoid reallocating every step)
  std::vector<Index> cursor;   ///< scratch
};

/// Groups the particles of `p` by slab. O(N) counting sort; flags particles outside the grid box.
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

/// Permutation that sorts particles by the linear index of their cell, for memory locality. Counting
/// sort: O(N + cells), stable, so the order (and hence the results) never depends on threads.
template <int Dim>
std::vector<Index> order_by_cell(const ParticleSet<Dim>& p, const GridGeometry<Dim>& g) {
  const Index n = p.size();
  Index cell_count = 1;
  for (int d = 0; d < Dim; ++d) cell_count *= g.cells(d);
  std::vector<Index> cell(n), offset(cell_count + 1, 0);
  for (Index i = 0; i < n; ++i) {
    Index c = 0, stride = 1;
    for (int d = 0; d < Dim; ++d) {
      const Real xi = (p.x[i][d] - g.origin[d]) * g.inv_h[d];
      const int k = std::isfinite(xi) ? std::clamp(static_cast<int>(xi), 0, g.cells(d) - 1) : 0;
      c += stride * k;
      stride *= g.cells(d);
    }
    cell[i] = c;
    ++offset[c + 1];
  }
  for (Index c = 0; c < cell_count; ++c) offset[c + 1] += offset[c];
  std::vector<Index> order(n);
  for (Index i = 0; i < n; ++i) order[offset[cell[i]]++] = i;
  return order;
}

}  // namespace mpm
