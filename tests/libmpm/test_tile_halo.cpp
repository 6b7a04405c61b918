// The ghost-node plan of a distributed run (tile_halo.hpp, docs/distributed.md §5.2), without MPI: the ranks are
// simulated in one process, each with its own copy of the nodes, and the messages of every rank's plan are
// delivered by hand in the order TileHalo sends and applies them. Whatever the owners of the tiles (slabs,
// bisected boxes, tiles dealt at random), every rank must end with the one-process sums, bit for bit, at every
// node its tiles reach; the bytes of a slab cut must be the (B + A) node layers of the overlap, each way once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <random>
#include <vector>

#include "mpm/parallel/tile_halo.hpp"

namespace {

using mpm::HaloMessage;
using mpm::HaloPlan;
using mpm::Index;
using mpm::TileGrid;

TileGrid grid_2d(int cells_x, int cells_y, int slab, int width, int below, int above) {
  TileGrid g;
  g.dim = 2;
  g.cells = {cells_x, cells_y, 1};
  g.nodes = {cells_x + 1, cells_y + 1, 1};
  g.tile_cells = {width, slab, 1};
  g.tiles = {(cells_x + width - 1) / width, (cells_y + slab - 1) / slab, 1};
  g.reach_below = below;
  g.reach_above = above;
  return g;
}

TileGrid grid_3d(int cells, int slab, int width, int below, int above) {
  TileGrid g;
  g.dim = 3;
  g.cells = {cells, cells + 3, cells};
  g.nodes = {cells + 1, cells + 4, cells + 1};
  g.tile_cells = {width, width, slab};
  for (int d = 0; d < 3; ++d) g.tiles[d] = (g.cells[d] + g.tile_cells[d] - 1) / g.tile_cells[d];
  g.reach_below = below;
  g.reach_above = above;
  return g;
}

Index node_index(const TileGrid& g, int i, int j, int k) { return i + Index{g.nodes[0]} * (j + Index{g.nodes[1]} * k); }

/// Calls f(node) for every node tile t reaches.
template <class F>
void for_each_reached(const TileGrid& g, Index t, F&& f) {
  const auto c = g.coordinates(t);
  std::array<std::pair<int, int>, 3> r{};
  for (int d = 0; d < 3; ++d) r[d] = d < g.dim ? g.reach(d, c[d]) : std::pair<int, int>{0, 0};
  for (int k = r[2].first; k <= r[2].second; ++k)
    for (int j = r[1].first; j <= r[1].second; ++j)
      for (int i = r[0].first; i <= r[0].second; ++i) f(node_index(g, i, j, k));
}

/// A contribution of tile t to node n whose sum with the others depends on their order (exponents spread over 30
/// decades).
double term(Index t, Index n) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(t) * 1000003u + static_cast<std::uint64_t>(n));
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-15, 15);
  return mantissa(rng) * std::ldexp(1.0, exponent(rng)) * (rng() % 2 ? 1.0 : -1.0);
}

/// Runs a scatter on `ranks` simulated ranks with the plans of `owner` and checks every rank's reached nodes against
/// the one-process sums, bit for bit. Returns the bytes (8 per node) each rank sent.
std::vector<std::size_t> run_and_compare(const TileGrid& g, const std::vector<int>& owner, int ranks) {
  const Index nodes = g.node_count();
  std::vector<double> serial(static_cast<std::size_t>(nodes), 0.0);
  for (int colour = 0; colour < g.colours(); ++colour)
    for (Index t = 0; t < g.tile_count(); ++t)
      if (g.colour(t) == colour) for_each_reached(g, t, [&](Index n) { serial[n] += term(t, n); });

  std::vector<HaloPlan> plan;
  for (int r = 0; r < ranks; ++r) plan.push_back(mpm::plan_halo(g, owner, r));
  // Both sides of a message list the same nodes.
  for (int r = 0; r < ranks; ++r)
    for (const HaloMessage& s : plan[r].sends) {
      const auto& in = plan[s.peer].receives;
      const auto it =
          std::find_if(in.begin(), in.end(), [&](const HaloMessage& m) { return m.colour == s.colour && m.peer == r; });
      EXPECT_TRUE(it != in.end() && it->runs == s.runs) << "rank " << r << " to " << s.peer << ", colour " << s.colour;
    }
  std::vector<std::vector<double>> copy(static_cast<std::size_t>(ranks), std::vector<double>(nodes, 0.0));
  // inbox[r][(colour, from)]: the values of that message, in the plan's node order
  std::vector<std::map<std::pair<int, int>, std::vector<double>>> inbox(static_cast<std::size_t>(ranks));
  std::vector<std::size_t> applied(static_cast<std::size_t>(ranks), 0), sent(static_cast<std::size_t>(ranks), 0);
  const auto apply = [&](int r, int below_colour) {
    auto& received = plan[r].receives;
    for (; applied[r] < received.size() && received[applied[r]].colour < below_colour; ++applied[r]) {
      const HaloMessage& m = received[applied[r]];
      const auto& values = inbox[r].at({m.colour, m.peer});
      std::size_t at = 0;
      for (const auto& [first, end] : m.runs)
        for (Index n = first; n < end; ++n) copy[r][n] = values[at++];
    }
  };
  for (int colour = 0; colour < g.colours(); ++colour)
    for (int r = 0; r < ranks; ++r) {
      apply(r, colour);
      for (const auto* list : {&plan[r].boundary_tiles[colour], &plan[r].inner_tiles[colour]})
        for (const Index t : *list) for_each_reached(g, t, [&](Index n) { copy[r][n] += term(t, n); });
      for (const HaloMessage& m : plan[r].sends) {
        if (m.colour != colour) continue;
        auto& values = inbox[m.peer][{m.colour, r}];
        for (const auto& [first, end] : m.runs)
          for (Index n = first; n < end; ++n) values.push_back(copy[r][n]);
        sent[r] += 8 * static_cast<std::size_t>(m.nodes);
      }
    }
  for (int r = 0; r < ranks; ++r) apply(r, g.colours());
  for (int r = 0; r < ranks; ++r) {
    int differing = 0;
    for (Index t = 0; t < g.tile_count(); ++t)
      if (owner[t] == r)
        for_each_reached(g, t,
                         [&](Index n) { differing += std::memcmp(&copy[r][n], &serial[n], sizeof(double)) != 0; });
    EXPECT_EQ(differing, 0) << "rank " << r << " of " << ranks;
  }
  // Every node has exactly one owner.
  for (Index n = 0; n < nodes; ++n) {
    int owners = 0;
    for (int r = 0; r < ranks; ++r) owners += plan[r].owned[n];
    EXPECT_EQ(owners, 1) << "node " << n;
  }
  return sent;
}

std::vector<int> random_owners(Index tiles, int ranks, std::mt19937& rng) {
  std::vector<int> owner(static_cast<std::size_t>(tiles));
  for (auto& o : owner) o = static_cast<int>(rng() % static_cast<unsigned>(ranks));
  std::vector<std::size_t> order(owner.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), rng);
  for (int r = 0; r < ranks; ++r) owner[order[r]] = r;
  return owner;
}

}  // namespace

// Two ranks cut between slabs: each sends the overlap once, (B + A) node layers of the whole axis 0, whatever the
// parity of the slab at the cut (hats B = 0, A = 1; cubic B-splines 2 / 3 with 5-cell slabs).
TEST(TileHalo, ASlabCutSendsTheOverlapLayersOnceEachWay) {
  for (const auto& [slab, below, above] : {std::array<int, 3>{2, 0, 1}, std::array<int, 3>{5, 2, 3}})
    for (int cut = 1; cut <= 3; ++cut) {
      const TileGrid g = grid_2d(30, 4 * slab, slab, 8, below, above);
      std::vector<int> owner(static_cast<std::size_t>(g.tile_count()));
      for (Index t = 0; t < g.tile_count(); ++t) owner[t] = g.coordinates(t)[1] >= cut ? 1 : 0;
      const auto sent = run_and_compare(g, owner, 2);
      const std::size_t layers = static_cast<std::size_t>(below + above);
      EXPECT_EQ(sent[0], 8 * layers * 31) << "slab " << slab << ", cut " << cut;
      EXPECT_EQ(sent[1], 8 * layers * 31) << "slab " << slab << ", cut " << cut;
    }
}

// Bisected boxes in 2D and 3D (hats, quadratic and cubic B-splines' reach): the one-process bits on every rank.
TEST(TileHalo, BisectedBoxesGiveTheOneProcessSums) {
  const TileGrid g2 = grid_2d(45, 37, 2, 8, 0, 1);
  std::vector<double> cost(static_cast<std::size_t>(g2.tile_count()));
  for (std::size_t t = 0; t < cost.size(); ++t) cost[t] = 1.0 + static_cast<double>(t % 7);
  for (int ranks : {2, 3, 4, 7}) {
    const auto owner = mpm::bisect_tiles(g2, cost, ranks);
    for (int r = 0; r < ranks; ++r) EXPECT_TRUE(mpm::plan_halo(g2, owner, r).is_box) << ranks << " ranks, rank " << r;
    run_and_compare(g2, owner, ranks);
  }
  const TileGrid g3 = grid_3d(17, 3, 8, 1, 2);
  std::vector<double> cost3(static_cast<std::size_t>(g3.tile_count()), 1.0);
  for (int ranks : {2, 4, 8}) run_and_compare(g3, mpm::bisect_tiles(g3, cost3, ranks), ranks);
}

// The per-axis cell flags of a box plan (HaloPlan::cell_flags, the post-step pass over the particles) answer, for
// every cell of the grid, what the cell's tile answers: outside the rank's box (bit 1), or outside or writing shared
// nodes (any bit). Bisected boxes in 2D and 3D with the reach of hats, quadratic and cubic B-splines, 2 to 8 ranks.
TEST(TileHalo, CellFlagsOfABoxAgreeWithTheTilesThatWriteSharedNodes) {
  const auto check = [](const TileGrid& g, int ranks) {
    std::vector<double> cost(static_cast<std::size_t>(g.tile_count()));
    for (std::size_t t = 0; t < cost.size(); ++t) cost[t] = 1.0 + static_cast<double>(t % 5);
    const auto owner = mpm::bisect_tiles(g, cost, ranks);
    const auto shared = mpm::shared_writing_tiles(g, owner);
    int compared = 0, writing = 0;
    for (int r = 0; r < ranks; ++r) {
      const HaloPlan plan = mpm::plan_halo(g, owner, r);
      ASSERT_TRUE(plan.is_box);
      std::array<int, 3> c{0, 0, 0};
      for (c[2] = 0; c[2] < (g.dim > 2 ? g.cells[2] : 1); ++c[2])
        for (c[1] = 0; c[1] < g.cells[1]; ++c[1])
          for (c[0] = 0; c[0] < g.cells[0]; ++c[0]) {
            unsigned any = 0;
            std::array<int, 3> tile{0, 0, 0};
            for (int d = 0; d < g.dim; ++d) {
              any |= plan.cell_flags[static_cast<std::size_t>(d)][static_cast<std::size_t>(c[d])];
              tile[d] = c[d] / g.tile_cells[d];
            }
            const auto t = static_cast<std::size_t>(g.index(tile));
            const bool outside = owner[t] != r;
            ASSERT_EQ((any & 1u) != 0, outside) << ranks << " ranks, rank " << r << ", tile " << t;
            ASSERT_EQ(any != 0, outside || shared[t] != 0) << ranks << " ranks, rank " << r << ", tile " << t;
            ++compared;
            writing += !outside && shared[t] != 0 ? 1 : 0;
          }
    }
    EXPECT_GT(writing, 0);  // the case has cells in tiles that write shared nodes, and others
    EXPECT_LT(writing, compared);
  };
  for (const auto& [below, above] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{2, 3}})
    for (int ranks : {2, 3, 4, 7}) check(grid_2d(45, 37, 3, 8, below, above), ranks);
  for (int ranks : {2, 4, 8}) check(grid_3d(17, 3, 8, 1, 2), ranks);
}

// Tiles dealt at random (the debug reassignment of the MPI tests): a node's writers on up to 2^d ranks.
TEST(TileHalo, TilesDealtAtRandomGiveTheOneProcessSums) {
  std::mt19937 rng(7);
  const TileGrid g2 = grid_2d(33, 24, 3, 8, 1, 2);
  for (int ranks : {2, 3, 5}) run_and_compare(g2, random_owners(g2.tile_count(), ranks, rng), ranks);
  const TileGrid g3 = grid_3d(17, 5, 8, 2, 3);
  for (int ranks : {3, 6}) run_and_compare(g3, random_owners(g3.tile_count(), ranks, rng), ranks);
}

// The bisection cuts the longest axis at the cost's weighted share of the ranks: two ranks on a square grid of
// uniform cost take a slab half each (the tie goes to the last axis); on a grid twice as wide, a half of axis 0.
TEST(TileHalo, BisectionCutsTheLongestAxisAtTheCostMedian) {
  const TileGrid square = grid_2d(32, 32, 2, 8, 0, 1);
  std::vector<double> cost(static_cast<std::size_t>(square.tile_count()), 1.0);
  auto owner = mpm::bisect_tiles(square, cost, 2);
  for (Index t = 0; t < square.tile_count(); ++t) EXPECT_EQ(owner[t], square.coordinates(t)[1] >= 8 ? 1 : 0);
  const TileGrid wide = grid_2d(64, 32, 2, 8, 0, 1);
  cost.assign(static_cast<std::size_t>(wide.tile_count()), 1.0);
  owner = mpm::bisect_tiles(wide, cost, 2);
  for (Index t = 0; t < wide.tile_count(); ++t) EXPECT_EQ(owner[t], wide.coordinates(t)[0] >= 4 ? 1 : 0);
  // All the cost in the first quarter of the slabs: the cut moves there.
  for (Index t = 0; t < square.tile_count(); ++t) cost[t] = square.coordinates(t)[1] < 4 ? 100.0 : 0.0;
  cost.resize(static_cast<std::size_t>(square.tile_count()));
  owner = mpm::bisect_tiles(square, cost, 2);
  for (Index t = 0; t < square.tile_count(); ++t) EXPECT_EQ(owner[t], square.coordinates(t)[1] >= 2 ? 1 : 0);
  EXPECT_THROW(mpm::bisect_tiles(square, cost, static_cast<int>(square.tile_count()) + 1), std::invalid_argument);
}
