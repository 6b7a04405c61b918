#pragma once
/// \file tile_binning.hpp
/// Race-free, deterministic particle-to-grid scatter without locks, on tiles with 2^d colours.
///
/// The grid is cut into tiles: `slab_cells` (`Shape::slab_cells`, the reach of the shape function) cells along
/// its last axis and `tile_width(slab_cells)` cells along each other axis; a particle belongs to the tile of its
/// cell. A row of tiles along the last axis is a **slab**. A distributed run's ranks own sets of tiles (tile_halo.hpp).
/// The colour of a tile is the parity of its coordinates (2^d colours); two tiles of one colour are at least one
/// tile apart on some axis, and a tile is at least as wide as a particle's reach, so the particles of two tiles of
/// a colour never reach the same node: all tiles of a colour scatter in parallel, colour after colour. The last
/// axis's parity is the most significant bit of the colour, so the colours 0 .. 2^(d-1) - 1 are the tiles of even
/// slabs and the others those of odd slabs: a slab round of the ghost-node protocol is 2^(d-1) tile rounds.
///
/// Inside a tile one task visits the particles in storage order, so every node receives its contributions in an
/// order that depends neither on the thread count nor on which rank owns which tile: colour by colour, and inside
/// a tile by storage order. The storage order is set by order_by_cell before the first step and every
/// `solver.sort_interval` steps (TLMPM: once): by (cell, id), a function of the particles' positions at that step
/// and their ids, not of where they sat in memory before, so results do not depend on the order of the input
/// either (docs/distributed.md §1).
///
/// Before, the threads scattered whole slabs (even slabs, then odd ones): at most slabs/2 tasks at a time, 26 on a
/// 256-cell axis with cubic B-splines; the tiles give a 256^3 grid 6,656 tasks per colour.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "mpm/core/parallel_chunks.hpp"
#include "mpm/grid/scatter_exchange.hpp"
#include "mpm/particles/particle_set.hpp"

namespace mpm {

/// Cells of a tile along every axis but the last: a power of two (a shift, not a division, per particle and axis
/// when binning) at least the reach `slab_cells` and at least 8, so that a tile's nodes are a few cache lines wide.
/// Even, so that the two-cell elements of Bernstein and Lagrange functions never straddle two tiles.
constexpr int tile_width(int slab_cells) {
  return static_cast<int>(std::bit_ceil(static_cast<unsigned>(std::max(8, slab_cells))));
}

struct TileBins {
  int dim = 1;
  int slab_cells = 1;                 ///< tile cells along the last axis (the slab of a distributed run)
  int width_shift = 3;                ///< tile cells along the other axes: 1 << width_shift
  std::array<int, 3> tiles{1, 1, 1};  ///< tiles per axis (the last used axis: slabs); unused axes 1
  int slab_count = 0;
  Index tiles_per_slab = 1;
  std::vector<Index> offsets;          ///< tile t holds order[offsets[t] .. offsets[t+1]); t first axis fastest
  std::vector<Index> order;            ///< particle indices grouped by tile, in storage order inside a tile
  Index outside = -1;                  ///< first particle found outside the grid box (or non-finite), -1 if none
  std::vector<std::uint32_t> tile_of;  ///< scratch: tile of each particle (kept to avoid reallocating every step)
  std::vector<Index> cursor;           ///< scratch
  std::array<std::vector<Index>, 3> tile_of_cell;  ///< scratch: per axis, cell -> tile coordinate x tile stride
  /// Distributed run: this rank's tiles and the ghost-node exchange after each colour (tile_halo.hpp); null in one
  /// process.
  const ScatterExchange* halo = nullptr;
  /// Distributed run: whether this step's scatters of these particles exchange ghost nodes. False when no particle
  /// of the body, on any rank, sits in a tile that writes a node several ranks hold (TileHalo::writes_shared): then
  /// the scatter leaves every ghost node as it was, equal on its holders, and waiting for the other ranks' rounds
  /// would only serialise the ranks (two bodies on two ranks: each rank waited for the other's body). Agreed by the
  /// step's one reduction (Simulation::take_step), true whenever that is not known.
  bool exchange = true;

  Index tile_count() const { return tiles_per_slab * slab_count; }
  /// 2^dim colours; colour c's tiles of slab parity c >> (dim - 1).
  int colours() const { return 1 << dim; }
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

/// The place of each cell in the storage order the scatter reads best: slab by slab; inside a slab the tiles of its
/// 2^(d-1) colours one colour after the other (so that a colour round reads the particles of a slab as one
/// contiguous run, not a tile's run and a gap of the same length); inside a colour tile by tile, first axis
/// fastest; inside a tile cell by cell, first axis fastest. (Sorted by the plain cell index instead, a tile's
/// particles were short runs with gaps and P2G with hats took 38-39 ns per particle-update against 26-31 for the
/// slabs: the particle fields missed the cache; docs/PERFORMANCE.md §17.) The places are unique, below count(),
/// and the same on every rank (a function of the grid and the shape function only).
template <int Dim>
class ScatterCellOrder {
 public:
  ScatterCellOrder(const GridGeometry<Dim>& g, int slab_cells)
      : g_(g), slab_cells_(slab_cells), shift_(std::countr_zero(static_cast<unsigned>(tile_width(slab_cells)))) {
    constexpr int last = Dim - 1;
    Index tiles_of_colour = 1;
    for (int d = 0; d < last; ++d) {
      cells_[d] = g.cells(d);
      half_tiles_[d] = ((((cells_[d] - 1) >> shift_) + 1) + 1) / 2;  // tiles of one parity, the larger count
      tiles_of_colour *= half_tiles_[d];
    }
    cells_[last] = g.cells(last);
    const Index slabs = (cells_[last] + slab_cells - 1) / slab_cells;
    tile_size_ = static_cast<Index>(slab_cells) << (shift_ * last);
    colour_size_ = tiles_of_colour * tile_size_;
    slab_size_ = colour_size_ << last;
    count_ = slabs * slab_size_;
  }
  Index count() const { return count_; }
  /// The place of the cell holding x (each axis clamped into the grid; non-finite coordinates: cell 0 of the axis).
  Index of(const VecU<Dim>& x) const {
    constexpr int last = Dim - 1;
    std::array<int, Dim> c{};
    for (int d = 0; d < Dim; ++d) {
      const Real xi = (x[d] - g_.origin[d]) * g_.inv_h[d];
      c[d] = std::isfinite(xi) ? std::clamp(static_cast<int>(xi), 0, cells_[d] - 1) : 0;
    }
    const int slab = c[last] / slab_cells_;
    Index local = c[last] - slab * slab_cells_;  // inside the tile: first axis fastest, the last slowest
    Index tile = 0;
    int colour = 0;
    const int mask = (1 << shift_) - 1;
    for (int d = last - 1; d >= 0; --d) {
      local = (local << shift_) | (c[d] & mask);
      const int t = c[d] >> shift_;
      colour |= (t & 1) << d;
      tile = tile * half_tiles_[d] + (t >> 1);
    }
    return slab * slab_size_ + colour * colour_size_ + tile * tile_size_ + local;
  }

 private:
  GridGeometry<Dim> g_;
  int slab_cells_;
  int shift_;
  std::array<int, Dim> cells_{};
  std::array<Index, Dim> half_tiles_{};
  Index tile_size_ = 1, colour_size_ = 1, slab_size_ = 1, count_ = 1;
};

/// The scatter key of a particle: the place of its cell (ScatterCellOrder), then its id. Unique while ids are (they
/// are per body).
inline std::uint64_t scatter_key(Index cell, std::uint32_t id) { return (static_cast<std::uint64_t>(cell) << 32) | id; }

/// Groups the particles of `p` by tile, in storage order inside a tile: an O(N) stable counting sort; flags
/// particles outside the grid box (they count as tile 0). The storage order is (cell, id) at the last sort
/// (order_by_cell, every `solver.sort_interval` steps, before the first step, and once for TLMPM).
template <int Dim>
void bin_by_tile(const ParticleSet<Dim>& p, const GridGeometry<Dim>& g, int slab_cells, TileBins& bins) {
  static_assert(Dim >= 1 && Dim <= 3);
  constexpr int last = Dim - 1;
  const int shift = std::countr_zero(static_cast<unsigned>(tile_width(slab_cells)));
  bins.dim = Dim;
  bins.slab_cells = slab_cells;
  bins.width_shift = shift;
  bins.tiles = {1, 1, 1};
  std::array<int, Dim> cells{};
  Index s = 1;
  for (int d = 0; d < Dim; ++d) {
    cells[d] = g.cells(d);
    bins.tiles[d] = d == last ? (cells[d] + slab_cells - 1) / slab_cells : ((cells[d] - 1) >> shift) + 1;
    // cell -> (tile coordinate x tile stride) on this axis: one load per axis and particle, no division
    auto& table = bins.tile_of_cell[d];
    table.resize(static_cast<std::size_t>(cells[d]));
    for (int c = 0; c < cells[d]; ++c)
      table[static_cast<std::size_t>(c)] = s * (d == last ? c / slab_cells : c >> shift);
    s *= bins.tiles[d];
  }
  bins.slab_count = bins.tiles[last];
  bins.tiles_per_slab = s / bins.slab_count;
  bins.outside = -1;
  const Index n = p.size();
  const Vec<Dim> lower = g.origin, upper = g.upper();
  auto& tile = bins.tile_of;
  tile.resize(static_cast<std::size_t>(n));
  bins.offsets.assign(static_cast<std::size_t>(bins.tile_count() + 1), 0);
  Index* count = bins.offsets.data() + 1;
  std::array<const Index*, Dim> table{};
  for (int d = 0; d < Dim; ++d) table[d] = bins.tile_of_cell[d].data();
  for (Index i = 0; i < n; ++i) {
    const auto& x = p.x[i];
    bool inside = true;
    for (int d = 0; d < Dim; ++d) inside = inside && x[d] >= lower[d] && x[d] <= upper[d];  // false for NaN
    if (!inside && bins.outside < 0) bins.outside = i;
    Index t = 0;
    if (inside)
      for (int d = 0; d < Dim; ++d)
        t += table[d][std::min(static_cast<int>((x[d] - g.origin[d]) * g.inv_h[d]), cells[d] - 1)];
    tile[i] = static_cast<std::uint32_t>(t);
    ++count[t];
  }
  const Index tiles = bins.tile_count();
  for (Index t = 0; t < tiles; ++t) bins.offsets[t + 1] += bins.offsets[t];
  bins.order.resize(static_cast<std::size_t>(n));
  bins.cursor.assign(bins.offsets.begin(), bins.offsets.end() - 1);
  for (Index i = 0; i < n; ++i) bins.order[bins.cursor[tile[i]]++] = i;
}

namespace detail {

/// Calls scatter(tile) in parallel for every tile of `colour`, skipping empty tiles.
template <class Scatter>
void scatter_colour(const TileBins& bins, int colour, Scatter&& scatter) {
  const int last = bins.dim - 1;
  const int slab_parity = colour >> last;
  // Tiles of the colour inside one slab: the product of ceil((tiles_d - parity_d) / 2) over the other axes.
  std::array<int, 2> along{1, 1};
  for (int d = 0; d < last; ++d) along[d] = (bins.tiles[d] - (colour >> d & 1) + 1) / 2;
  const Index per_slab = static_cast<Index>(along[0]) * along[1];
  const Index slab_runs = (bins.slab_count - slab_parity + 1) / 2;
  const Index total = per_slab * slab_runs;
  if (total <= 0) return;
  parallel_chunks(Index{0}, total, 1, [&](Index chunk_begin, Index chunk_end) {
    for (Index k = chunk_begin; k != chunk_end; ++k) {
      const Index run = k / per_slab, in_slab = k % per_slab;
      const Index slab = 2 * run + slab_parity;
      Index t = slab * bins.tiles_per_slab;
      const Index a0 = in_slab % along[0], a1 = in_slab / along[0];
      if (last >= 1) t += 2 * a0 + (colour & 1);
      if (last >= 2) t += bins.tiles[0] * (2 * a1 + (colour >> 1 & 1));
      const Index begin = bins.offsets[t], end = bins.offsets[t + 1];
      if (end > begin) scatter(bins.order.data() + begin, end - begin);
    }
  });
}

/// Calls scatter(tile) in parallel for the listed tiles (a distributed rank's, of one colour), skipping empty ones.
template <class Scatter>
void scatter_tiles(const TileBins& bins, const std::vector<Index>& tiles, Scatter&& scatter) {
  if (tiles.empty()) return;
  parallel_chunks(std::size_t{0}, tiles.size(), 1, [&](std::size_t chunk_begin, std::size_t chunk_end) {
    for (std::size_t k = chunk_begin; k != chunk_end; ++k) {
      const Index t = tiles[k];
      const Index begin = bins.offsets[t], end = bins.offsets[t + 1];
      if (end > begin) scatter(bins.order.data() + begin, end - begin);
    }
  });
}

}  // namespace detail

/// Calls body(indices, count) for every non-empty tile, colour after colour, the tiles of a colour in parallel.
/// `written`: the nodal arrays the body adds to; in a distributed run (bins.halo) a rank scatters its own tiles and
/// their ghost nodes are exchanged after each colour (tile_halo.hpp): the tiles of a colour that write nodes sent
/// after it scatter first and the message leaves while the others scatter. Tiles of one colour write disjoint nodes,
/// so that order changes no bit.
template <class Body>
void for_each_tile_coloured(const TileBins& bins, std::span<const HaloArray> written, Body&& body) {
  const ScatterExchange* halo = bins.halo;
  if (!halo) {
    for (int colour = 0; colour < bins.colours(); ++colour) detail::scatter_colour(bins, colour, body);
    return;
  }
  if (halo->tile_count() != bins.tile_count())
    throw std::logic_error("for_each_tile_coloured: the bins and the halo tile the grid differently");
  if (!bins.exchange) {  // no ghost node changes: the same tiles in the same order, no message
    for (int colour = 0; colour < bins.colours(); ++colour) {
      detail::scatter_tiles(bins, halo->boundary_tiles(colour), body);
      detail::scatter_tiles(bins, halo->inner_tiles(colour), body);
    }
    return;
  }
  halo->begin_scatter(written);
  for (int colour = 0; colour < bins.colours(); ++colour) {
    halo->before_round(colour);
    detail::scatter_tiles(bins, halo->boundary_tiles(colour), body);
    halo->send(colour);
    detail::scatter_tiles(bins, halo->inner_tiles(colour), body);
  }
  halo->end_scatter();
}
template <class Body>
void for_each_tile_coloured(const TileBins& bins, std::initializer_list<HaloArray> written, Body&& body) {
  for_each_tile_coloured(bins, std::span<const HaloArray>(written.begin(), written.size()), std::forward<Body>(body));
}

/// A scatter whose arrays have no halo yet (the modules that a distributed run refuses, Simulation::distribute).
template <class Body>
void for_each_tile_coloured(const TileBins& bins, Body&& body) {
  if (bins.halo) throw std::logic_error("a scatter without ghost-node exchange ran in a distributed run");
  for_each_tile_coloured(bins, {}, std::forward<Body>(body));
}

/// The working arrays of order_by_cell, kept between sorts. Fresh arrays cost a page fault per 4 KiB page on first
/// touch (memset and faults were 0.13-0.20 s of a 40-step run of a rank on this VM, more than the sort itself:
/// docs/PERFORMANCE.md §16.6); kept, a sort touches memory it already owns.
struct CellSortBuffers {
  std::vector<std::uint64_t> key, sorted;
  std::vector<Index> start;
  std::vector<Index> order;  ///< the result: new[i] = old[order[i]]
};

/// Permutation that sorts particles by their scatter key (the place of their cell in ScatterCellOrder, then id):
/// after it the storage order, and so the scatter order inside a tile, depends on the particles' positions and ids
/// only, whatever it was before. `slab_cells`: the shape function's (Shape::slab_cells, the tiles of bin_by_tile).
/// A counting sort by cell, O(N + the cells from the particles' first to their last place), stable (so the particles of
/// a cell come in their previous storage order, which is id order when they were sorted before and have not changed
/// cells), then an insertion sort of the ids inside each cell, which moves a particle only past the few of its own cell
/// with a larger id; a storage far from that order (a first sort of a shuffled input with many particles per cell)
/// falls back to a sort of the keys beyond 8 moves per particle. Returns `buffers.order`; `buffers.sorted` then holds
/// the keys in the new order (a distributed run keeps them as its particles' scatter_key_field).
template <int Dim>
const std::vector<Index>& order_by_cell(const ParticleSet<Dim>& p, const GridGeometry<Dim>& g, int slab_cells,
                                        CellSortBuffers& buffers) {
  const Index n = p.size();
  auto& order = buffers.order;
  order.resize(static_cast<std::size_t>(n));
  if (n == 0) return order;  // an empty set (a body on another rank): no pass over the cells
  const ScatterCellOrder<Dim> place(g, slab_cells);
  const Index cell_count = place.count();
  auto& key = buffers.key;
  auto& sorted = buffers.sorted;
  auto& start = buffers.start;
  key.resize(static_cast<std::size_t>(n));
  sorted.resize(static_cast<std::size_t>(n));
  // The counts cover the places from the lowest to the highest the particles hold, not the whole grid: a body in a
  // corner, or a rank's share, zeroes and sums a fraction of the cells' counts.
  Index lo = cell_count, hi = 0;
  for (Index i = 0; i < n; ++i) {
    const Index cell = place.of(p.x[i]);
    key[i] = scatter_key(cell, p.id[i]);
    lo = std::min(lo, cell);
    hi = std::max(hi, cell);
  }
  const Index span = hi - lo + 1;
  start.assign(static_cast<std::size_t>(span + 1), 0);
  for (Index i = 0; i < n; ++i) ++start[static_cast<Index>(key[i] >> 32) - lo + 1];
  for (Index c = 0; c < span; ++c) start[c + 1] += start[c];
  for (Index i = 0; i < n; ++i) {
    const Index k = start[static_cast<Index>(key[i] >> 32) - lo]++;
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
      for (Index m = 0; m < n; ++m) order[m] = m;
      std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return key[a] < key[b]; });
      for (Index m = 0; m < n; ++m) sorted[m] = key[order[m]];
      return order;
    }
  }
  return order;
}

/// The same with arrays of its own (a sort that runs once: TLMPM's, tests).
template <int Dim>
std::vector<Index> order_by_cell(const ParticleSet<Dim>& p, const GridGeometry<Dim>& g, int slab_cells) {
  CellSortBuffers buffers;
  order_by_cell(p, g, slab_cells, buffers);
  return std::move(buffers.order);
}

}  // namespace mpm
