// The fixed global tiling of distributed runs and its model (mpm/tiling.hpp, docs/distributed.md §2): tile
// counts, colours, the reach of each shape function against its evaluation, the cut into ranks and the ghost
// nodes against counts made by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "mpm/shape/shape_functions.hpp"
#include "mpm/tiling.hpp"

namespace mpm {
namespace {

template <int Dim>
GridGeometry<Dim> grid(const std::array<int, Dim>& cells) {
  return GridGeometry<Dim>(Vec<Dim>::Zero(), Vec<Dim>::Ones(), cells);
}

/// One particle in every cell of the grid (linear cell indices).
template <int Dim>
std::vector<Index> every_cell(const Tiling<Dim>& t) {
  Index n = 1;
  for (int d = 0; d < Dim; ++d) n *= t.cells[d];
  std::vector<Index> cells(n);
  for (Index i = 0; i < n; ++i) cells[i] = i;
  return cells;
}

TEST(Tiling, TilesCoverTheGridAndDoNotDependOnRanks) {
  const Tiling<2> t = make_tiling<2>(grid<2>({20, 12}), LinearHat::slab_cells);
  EXPECT_EQ(t.tile_cells, 8);
  EXPECT_EQ(t.tiles[0], 3);  // 8 + 8 + 4 cells
  EXPECT_EQ(t.tiles[1], 2);  // 8 + 4
  EXPECT_EQ(t.tile_count(), 6);
  EXPECT_EQ(t.tile_of_node(0, 8), 1);   // the node between two tiles belongs to the upper one
  EXPECT_EQ(t.tile_of_node(0, 20), 2);  // the grid's last node to the last tile
  EXPECT_EQ(t.tile_of_node(1, 12), 1);
  for (Index i = 0; i < t.tile_count(); ++i) EXPECT_EQ(t.index(t.coordinates(i)), i);
  // A reach wider than the default tile widens every tile, to an even number of cells (two-cell elements).
  EXPECT_EQ(make_tiling<2>(grid<2>({40, 40}), 9).tile_cells, 10);
}

TEST(Tiling, TilesOfOneColourAreNeverNeighbours) {
  const Tiling<3> t = make_tiling<3>(grid<3>({40, 24, 16}), 2);
  for (Index a = 0; a < t.tile_count(); ++a)
    for (Index b = a + 1; b < t.tile_count(); ++b) {
      const auto ta = t.coordinates(a), tb = t.coordinates(b);
      int far = 0;
      for (int d = 0; d < 3; ++d) far = std::max(far, std::abs(ta[d] - tb[d]));
      if (far == 1) {
        EXPECT_NE(Tiling<3>::colour(ta), Tiling<3>::colour(tb));
      }
    }
}

TEST(Tiling, MortonKeyInterleavesTheCoordinates) {
  EXPECT_EQ(morton_key<2>({1, 0}), 1u);
  EXPECT_EQ(morton_key<2>({0, 1}), 2u);
  EXPECT_EQ(morton_key<2>({1, 1}), 3u);
  EXPECT_EQ(morton_key<2>({2, 0}), 4u);
  EXPECT_EQ(morton_key<3>({0, 0, 1}), 4u);
  EXPECT_EQ(morton_key<3>({3, 0, 0}), 9u);
  EXPECT_EQ(morton_key<1>({12345}), 12345u);
}

// The reach of every shape function with a one-axis evaluation, sampled across the cells of an axis: the nodes
// it gives weight to lie in [c - below, c + above] inside the grid, except next to the faces, where the face
// splines may reach one node further but never out of the face's tile; and two tiles of one colour are far
// enough apart that their particles share no node.
TEST(Tiling, CellReachContainsEveryShapeFunctionsStencil) {
  int checked = 0;
  for_each_shape([&]<class Shape>() {
    if constexpr (requires(Real xi, int n, int& b, Real* w) { Shape::evaluate(xi, n, b, w, w); }) {
      const int nodes = 33;
      const CellReach reach = cell_reach(Shape::support);
      const Tiling<1> tiling = make_tiling<1>(grid<1>({nodes - 1}), Shape::slab_cells);
      EXPECT_LE(reach.below + reach.above, tiling.tile_cells) << Shape::name;
      for (int s = 0; s < 3200; ++s) {
        const Real xi = (s + 0.37) / 100.0;
        const int c = static_cast<int>(xi);
        int base = 0;
        Real w[8], dw[8];
        Shape::evaluate(xi, nodes, base, w, dw);
        const bool face = c < 1 || c > nodes - 3;
        for (int k = 0; k < Shape::support; ++k) {
          if (w[k] == 0) continue;
          const int node = base + k;
          if (face) {
            EXPECT_EQ(tiling.tile_of_node(0, node), tiling.tile_of_cell(c)) << Shape::name << " xi " << xi;
          } else {
            EXPECT_GE(node, c - reach.below) << Shape::name << " xi " << xi;
            EXPECT_LE(node, c + reach.above) << Shape::name << " xi " << xi;
          }
        }
      }
      ++checked;
    }
  });
  EXPECT_GE(checked, 5);  // linear, quadratic and cubic B-splines, Bernstein, Lagrange
  EXPECT_EQ(cell_reach(2).below, 0);
  EXPECT_EQ(cell_reach(2).above, 1);
  EXPECT_EQ(cell_reach(6).below, 2);  // CPDI of reach 2: c-2..c+3
  EXPECT_EQ(cell_reach(6).above, 3);
}

// 32 cells in 4 tiles, one particle per cell, on 2 ranks: tiles 0-1 and 2-3. Linear hats: the particle of cell
// 15 reaches node 16 of rank 1's tile: 1 ghost node. Quadratic B-splines (c-1..c+2): rank 0 reaches 16 and 17,
// rank 1 reaches 15: 3.
TEST(DecompositionModel, GhostNodesOfA1DCutCountedByHand) {
  const Tiling<1> t = make_tiling<1>(grid<1>({32}), 2);
  const auto linear = model_decomposition<1>(t, every_cell(t), 2, 2);
  ASSERT_EQ(linear.ranks.size(), 2u);
  EXPECT_EQ(linear.ranks[0].tiles, 2);
  EXPECT_EQ(linear.ranks[0].particles, 16);
  EXPECT_EQ(linear.ranks[1].particles, 16);
  EXPECT_EQ(linear.ranks[0].ghost_nodes, 1);
  EXPECT_EQ(linear.ranks[1].ghost_nodes, 0);
  // Costs: 8 particles x 2 stencil nodes + 8 owned nodes per tile, 9 for the last: 24 + 24 against 24 + 25.
  EXPECT_DOUBLE_EQ(linear.ranks[0].cost, 48);
  EXPECT_DOUBLE_EQ(linear.ranks[1].cost, 49);
  EXPECT_DOUBLE_EQ(linear.imbalance(), 49.0 / 48.5);
  const auto quadratic = model_decomposition<1>(t, every_cell(t), 3, 2);
  EXPECT_EQ(quadratic.ranks[0].ghost_nodes, 2);
  EXPECT_EQ(quadratic.ranks[1].ghost_nodes, 1);
  EXPECT_EQ(quadratic.ghost_nodes(), 3);
  EXPECT_EQ(quadratic.occupied_tiles, 4);
}

// 16 x 16 cells, 4 tiles, 2 ranks: Morton order (0,0) (1,0) (0,1) (1,1) gives rank 0 the lower row of tiles. The
// particles of cell row 7 reach node row 8, rank 1's: 17 ghost nodes with linear hats, none the other way.
TEST(DecompositionModel, GhostNodesOfA2DCutCountedByHand) {
  const Tiling<2> t = make_tiling<2>(grid<2>({16, 16}), 2);
  const auto m = model_decomposition<2>(t, every_cell(t), 2, 2);
  EXPECT_EQ(m.rank_of_tile[t.index({0, 0})], 0);
  EXPECT_EQ(m.rank_of_tile[t.index({1, 0})], 0);
  EXPECT_EQ(m.rank_of_tile[t.index({0, 1})], 1);
  EXPECT_EQ(m.rank_of_tile[t.index({1, 1})], 1);
  EXPECT_EQ(m.ranks[0].ghost_nodes, 17);
  EXPECT_EQ(m.ranks[1].ghost_nodes, 0);
  // On 4 ranks each owns one tile; rank 0 (lower left) reaches column 8 and row 8: 9 + 9 - 1 = 17 nodes.
  const auto four = model_decomposition<2>(t, every_cell(t), 2, 4);
  for (const auto& r : four.ranks) EXPECT_EQ(r.particles, 64);
  EXPECT_EQ(four.ranks[0].ghost_nodes, 17);
}

// Particles in one corner: the tiles out of their reach cost nothing, the busiest tile bounds the most loaded
// rank, and no cut of the curve does better than the cut found (checked against every cut for 2 ranks).
TEST(DecompositionModel, CutIsTheBestContiguousOneAndSparseTilesAreFree) {
  const Tiling<2> t = make_tiling<2>(grid<2>({32, 32}), 2);
  std::vector<Index> cells;
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i)
      for (int k = 0; k < 1 + (i + j) % 3; ++k) cells.push_back(i + 32 * j);
  const auto m = model_decomposition<2>(t, cells, 2, 2);
  EXPECT_EQ(m.occupied_tiles, 4);
  EXPECT_EQ(m.active_tiles, 4);  // cells 0..11 reach nodes 0..12: tiles 0 and 1 of each axis
  EXPECT_EQ(m.ranks[0].particles + m.ranks[1].particles, static_cast<Index>(cells.size()));
  const auto one = model_decomposition<2>(t, cells, 2, 1);
  const double total = one.ranks[0].cost;
  // Every cut of the 16 tiles in Morton order into two runs: the best largest cost.
  std::vector<Index> order(16);
  for (Index i = 0; i < 16; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](Index a, Index b) { return morton_key<2>(t.coordinates(a)) < morton_key<2>(t.coordinates(b)); });
  double best = total;
  for (int cut = 0; cut <= 16; ++cut) {
    double first = 0;
    for (int i = 0; i < cut; ++i) {
      // The cost of a tile: its particles x 4 + its nodes when active.
      const auto c = t.coordinates(order[i]);
      Index particles = 0;
      for (const Index cell : cells)
        if (static_cast<int>(cell % 32) / 8 == c[0] && static_cast<int>(cell / 32) / 8 == c[1]) ++particles;
      const bool active = c[0] <= 1 && c[1] <= 1;
      first += 4.0 * particles + (active ? 64.0 : 0.0);
    }
    best = std::min(best, std::max(first, total - first));
  }
  EXPECT_DOUBLE_EQ(std::max(m.ranks[0].cost, m.ranks[1].cost), best);
}

}  // namespace
}  // namespace mpm
