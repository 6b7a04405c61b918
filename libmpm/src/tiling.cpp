#include "mpm/tiling.hpp"

#include <algorithm>
#include <numeric>

namespace mpm {

template <int Dim>
Tiling<Dim> make_tiling(const GridGeometry<Dim>& g, int slab_cells) {
  Tiling<Dim> t;
  t.tile_cells = std::max(default_tile_cells, slab_cells);
  t.tile_cells += t.tile_cells % 2;  // even: the two-cell elements of Bernstein and Lagrange never straddle tiles
  for (int d = 0; d < Dim; ++d) {
    t.cells[d] = g.cells(d);
    t.tiles[d] = (t.cells[d] + t.tile_cells - 1) / t.tile_cells;
  }
  return t;
}

CellReach cell_reach(int support) {
  // The base node of an even support is the cell's lower node minus (support - 2)/2 wherever the particle
  // sits in the cell; an odd support's base moves by one at the cell's middle (quadratic B-spline, eq. 3.8).
  CellReach r;
  r.below = (support - 1) / 2;
  r.above = support - 1 - r.below + (support % 2);
  return r;
}

int halo_doubles_per_node(int dim, const std::string& scheme) {
  const int scatter = 1 + 2 * dim;  // mass, momentum, force (USF's two passes carry the same fields)
  return scheme == "musl" ? scatter + dim : scatter;
}

Index DecompositionModel::ghost_nodes() const {
  Index n = 0;
  for (const auto& r : ranks) n += r.ghost_nodes;
  return n;
}

double DecompositionModel::imbalance() const {
  double total = 0, most = 0;
  for (const auto& r : ranks) {
    total += r.cost;
    most = std::max(most, r.cost);
  }
  return total > 0 ? most * static_cast<double>(ranks.size()) / total : 1.0;
}

template <int Dim>
std::uint64_t morton_key(const std::array<int, Dim>& t) {
  std::uint64_t key = 0;
  for (int bit = 0; bit < std::min(32, 64 / Dim); ++bit)
    for (int d = 0; d < Dim; ++d)
      key |= static_cast<std::uint64_t>((static_cast<unsigned>(t[d]) >> bit) & 1u) << (bit * Dim + d);
  return key;
}

namespace {

/// Calls f(node coordinates) for every node a particle in cell `c` reaches, clipped to the grid.
template <int Dim, class F>
void for_each_reached_node(const Tiling<Dim>& tiling, const std::array<int, Dim>& c, CellReach reach, F&& f) {
  std::array<int, Dim> lo{}, hi{}, n{};
  for (int d = 0; d < Dim; ++d) {
    lo[d] = std::max(0, c[d] - reach.below);
    hi[d] = std::min(tiling.cells[d], c[d] + reach.above);
    n[d] = lo[d];
  }
  while (true) {
    f(n);
    int d = 0;
    for (; d < Dim; ++d) {
      if (++n[d] <= hi[d]) break;
      n[d] = lo[d];
    }
    if (d == Dim) return;
  }
}

template <int Dim>
std::array<int, Dim> cell_coordinates(Index cell, const std::array<int, Dim>& cells) {
  std::array<int, Dim> c{};
  for (int d = 0; d < Dim; ++d) {
    c[d] = static_cast<int>(cell % cells[d]);
    cell /= cells[d];
  }
  return c;
}

/// Nodes a tile owns: its cells per axis, plus the grid's last node row on the last tile of an axis.
template <int Dim>
Index owned_nodes(const Tiling<Dim>& tiling, const std::array<int, Dim>& t) {
  Index n = 1;
  for (int d = 0; d < Dim; ++d) {
    const int first = t[d] * tiling.tile_cells;
    const int last = std::min(tiling.cells[d], first + tiling.tile_cells) - 1;
    n *= last - first + 1 + (t[d] == tiling.tiles[d] - 1 ? 1 : 0);
  }
  return n;
}

}  // namespace

template <int Dim>
DecompositionModel model_decomposition(const Tiling<Dim>& tiling, const std::vector<Index>& cells, int support,
                                       int ranks) {
  DecompositionModel m;
  m.tiles = tiling.tile_count();
  const CellReach reach = cell_reach(support);
  auto tile_of_cell = [&](const std::array<int, Dim>& c) {
    std::array<int, Dim> t{};
    for (int d = 0; d < Dim; ++d) t[d] = tiling.tile_of_cell(c[d]);
    return tiling.index(t);
  };
  auto tile_of_node = [&](const std::array<int, Dim>& n) {
    std::array<int, Dim> t{};
    for (int d = 0; d < Dim; ++d) t[d] = tiling.tile_of_node(d, n[d]);
    return tiling.index(t);
  };
  // Particles per occupied cell (sorted, so that everything below visits cells in one order).
  std::vector<Index> sorted = cells;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::pair<Index, Index>> occupied;  // (cell, particles)
  for (const Index c : sorted)
    if (!occupied.empty() && occupied.back().first == c)
      ++occupied.back().second;
    else
      occupied.emplace_back(c, 1);
  std::vector<Index> particles(m.tiles, 0);
  std::vector<char> active(m.tiles, 0);
  for (const auto& [cell, count] : occupied) {
    const auto c = cell_coordinates<Dim>(cell, tiling.cells);
    particles[tile_of_cell(c)] += count;
    for_each_reached_node<Dim>(tiling, c, reach, [&](const std::array<int, Dim>& n) { active[tile_of_node(n)] = 1; });
  }
  // Cost per tile, then the Morton order cut into `ranks` runs by the midpoint of each tile's cost.
  double stencil = 1;
  for (int d = 0; d < Dim; ++d) stencil *= support;
  std::vector<double> cost(m.tiles, 0);
  for (Index t = 0; t < m.tiles; ++t) {
    m.occupied_tiles += particles[t] > 0;
    m.active_tiles += active[t];
    cost[t] = static_cast<double>(particles[t]) * stencil +
              (active[t] ? static_cast<double>(owned_nodes<Dim>(tiling, tiling.coordinates(t))) : 0.0);
  }
  std::vector<Index> order(m.tiles);
  std::iota(order.begin(), order.end(), Index{0});
  std::vector<std::uint64_t> key(m.tiles);
  for (Index t = 0; t < m.tiles; ++t) key[t] = morton_key<Dim>(tiling.coordinates(t));
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return key[a] < key[b]; });
  // The smallest bound on a rank's cost for which cutting the curve greedily needs at most `ranks` runs
  // (chains-on-chains partitioning by bisection on the bound): the most loaded rank is then as light as any
  // contiguous cut of the curve allows.
  auto runs_needed = [&](double bound) {
    int runs = 1;
    double run = 0;
    for (const Index t : order) {
      if (run > 0 && run + cost[t] > bound) {
        ++runs;
        run = 0;
      }
      run += cost[t];
    }
    return runs;
  };
  const double total = std::accumulate(cost.begin(), cost.end(), 0.0);
  double low = std::max(*std::max_element(cost.begin(), cost.end()), total / ranks), high = std::max(total, low);
  for (int i = 0; i < 100 && high - low > 1e-9 * high; ++i) {
    const double mid = 0.5 * (low + high);
    (runs_needed(mid) <= ranks ? high : low) = mid;
  }
  m.rank_of_tile.assign(m.tiles, 0);
  m.ranks.assign(ranks, RankShare{});
  int r = 0;
  double run = 0;
  for (const Index t : order) {
    if (run > 0 && run + cost[t] > high && r + 1 < ranks) {
      ++r;
      run = 0;
    }
    run += cost[t];
    m.rank_of_tile[t] = r;
    m.ranks[r].tiles += 1;
    m.ranks[r].particles += particles[t];
    m.ranks[r].cost += cost[t];
  }
  // Ghost nodes: (node, rank) pairs where a rank's particles reach a node of another rank's tile.
  std::vector<std::uint64_t> ghosts;
  for (const auto& [cell, count] : occupied) {
    const auto c = cell_coordinates<Dim>(cell, tiling.cells);
    const int r = m.rank_of_tile[tile_of_cell(c)];
    for_each_reached_node<Dim>(tiling, c, reach, [&](const std::array<int, Dim>& n) {
      if (m.rank_of_tile[tile_of_node(n)] == r) return;
      Index node = 0, stride = 1;
      for (int d = 0; d < Dim; ++d) {
        node += stride * n[d];
        stride *= tiling.cells[d] + 1;
      }
      ghosts.push_back(static_cast<std::uint64_t>(node) * static_cast<std::uint64_t>(ranks) +
                       static_cast<std::uint64_t>(r));
    });
  }
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  for (const auto g : ghosts) ++m.ranks[g % static_cast<std::uint64_t>(ranks)].ghost_nodes;
  return m;
}

#define MPM_INSTANTIATE_TILING(D)                                  \
  template Tiling<D> make_tiling<D>(const GridGeometry<D>&, int);  \
  template std::uint64_t morton_key<D>(const std::array<int, D>&); \
  template DecompositionModel model_decomposition<D>(const Tiling<D>&, const std::vector<Index>&, int, int);
MPM_INSTANTIATE_TILING(1)
MPM_INSTANTIATE_TILING(2)
MPM_INSTANTIATE_TILING(3)
#undef MPM_INSTANTIATE_TILING

}  // namespace mpm
