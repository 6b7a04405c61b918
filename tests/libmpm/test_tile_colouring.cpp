// The threaded scatter's tiles (tile_binning.hpp): tiles of one colour never write a common node, every particle
// is visited exactly once, colour after colour, and a node's contributions come in the same order whichever tiles
// a colour's tasks take first.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <random>
#include <set>

#include <tbb/global_control.h>

#include "mpm/grid/tile_binning.hpp"
#include "mpm/shape/cubic_bspline.hpp"
#include "mpm/shape/gimp.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "mpm/shape/quadratic_bspline.hpp"
#include "mpm/shape/stencil.hpp"

namespace mpm {
namespace {

/// `n` particles at random in a grid of `cells` per axis (h = 1), faces included; ids 0 .. n - 1.
template <int Dim>
ParticleSet<Dim> scattered(int n, int cells, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(0, cells);
  ParticleSet<Dim> p;
  for (int i = 0; i < n; ++i) {
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = i % 17 == 0 ? (i % 2 ? 0 : cells) : u(rng);  // some on the faces
    p.add(x, 1, 1);
  }
  return p;
}

/// For each colour: the tiles its tasks visit write disjoint node sets (every node of each particle's stencil,
/// zero weights included), and over all colours every particle is visited once.
template <int Dim, class Shape>
void check_colouring(int cells) {
  std::mt19937 rng(5);
  const ParticleSet<Dim> p = scattered<Dim>(4000, cells, rng);
  std::array<int, Dim> n;
  n.fill(cells);
  const GridGeometry<Dim> g(Vec<Dim>::Zero(), Vec<Dim>::Ones(), n);
  TileBins bins;
  bin_by_tile(p, g, Shape::slab_cells, bins);
  ASSERT_EQ(bins.outside, -1);
  EXPECT_GE(tile_width(Shape::slab_cells), Shape::slab_cells);
  // One scatter, recording for every call its tile's colour and the nodes its particles write.
  struct Call {
    int colour;
    std::set<Index> nodes;
  };
  std::vector<Call> calls;
  std::vector<int> visits(static_cast<std::size_t>(p.size()), 0);
  std::mutex m;
  for_each_tile_coloured(bins, [&](const Index* index, Index count) {
    Stencil<Dim, Shape> st;
    Call call;
    for (Index k = 0; k < count; ++k) {
      st.compute(p.x[index[k]], g, Vec<Dim>::Constant(0.5));
      for (int a = 0; a < st.count; ++a) call.nodes.insert(st.node[a]);
    }
    const auto first = static_cast<Index>(index - bins.order.data());
    Index t = std::upper_bound(bins.offsets.begin(), bins.offsets.end(), first) - bins.offsets.begin() - 1;
    call.colour = 0;
    for (int d = 0; d < Dim; ++d) {
      call.colour |= static_cast<int>(t % bins.tiles[d] & 1) << d;  // bit d: the parity of coordinate d
      t /= bins.tiles[d];
    }
    const std::scoped_lock lock(m);
    for (Index k = 0; k < count; ++k) ++visits[static_cast<std::size_t>(index[k])];
    calls.push_back(std::move(call));
  });
  for (std::size_t i = 0; i < visits.size(); ++i) ASSERT_EQ(visits[i], 1) << Shape::name << ": particle " << i;
  // Colours one after the other (a colour's tasks all end before the next colour starts) ...
  for (std::size_t k = 1; k < calls.size(); ++k) ASSERT_LE(calls[k - 1].colour, calls[k].colour) << Shape::name;
  // ... and inside a colour no node written twice.
  std::map<Index, int> writes;
  for (std::size_t k = 0; k < calls.size(); ++k) {
    if (k > 0 && calls[k].colour != calls[k - 1].colour) writes.clear();
    for (Index node : calls[k].nodes)
      ASSERT_EQ(++writes[node], 1) << Shape::name << ": node " << node << " written by two tiles of colour "
                                   << calls[k].colour;
  }
  EXPECT_EQ(calls.front().colour, 0);
  EXPECT_EQ(calls.back().colour, bins.colours() - 1);
}

TEST(TileColouring, TilesOfAColourWriteDisjointNodesIn2D) {
  check_colouring<2, LinearHat>(37);
  check_colouring<2, QuadraticBSpline>(37);
  check_colouring<2, CubicBSpline>(41);
  check_colouring<2, UGimp>(41);
}

TEST(TileColouring, TilesOfAColourWriteDisjointNodesIn3D) {
  check_colouring<3, LinearHat>(19);
  check_colouring<3, CubicBSpline>(21);
}

/// Every cell has its own place in ScatterCellOrder, below count(); and particles sorted by it are read front to back
/// by a one-thread scatter (a colour round reads each slab's run of that colour in one sweep), which is what keeps
/// the particle fields streaming from memory.
template <int Dim, class Shape>
void check_storage_order(std::array<int, Dim> cells) {
  const GridGeometry<Dim> g(Vec<Dim>::Zero(), Vec<Dim>::Ones(), cells);
  const ScatterCellOrder<Dim> place(g, Shape::slab_cells);
  std::set<Index> places;
  Index cell_count = 1;
  for (int d = 0; d < Dim; ++d) cell_count *= cells[d];
  for (Index c = 0; c < cell_count; ++c) {
    VecU<Dim> x;
    Index rest = c;
    for (int d = 0; d < Dim; ++d) {
      x[d] = static_cast<Real>(rest % cells[d]) + 0.5;
      rest /= cells[d];
    }
    const Index k = place.of(x);
    ASSERT_GE(k, 0);
    ASSERT_LT(k, place.count());
    ASSERT_TRUE(places.insert(k).second) << Shape::name << ": two cells at place " << k;
  }
  std::mt19937 rng(3);
  ParticleSet<Dim> p = scattered<Dim>(5000, cells[0], rng);
  for (Index i = 0; i < p.size(); ++i)
    for (int d = 1; d < Dim; ++d) p.x[i][d] *= static_cast<Real>(cells[d]) / cells[0];
  p.gather(order_by_cell(p, g, Shape::slab_cells));
  TileBins bins;
  bin_by_tile(p, g, Shape::slab_cells, bins);
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  std::vector<Index> read;
  for_each_tile_coloured(bins, [&](const Index* index, Index count) { read.insert(read.end(), index, index + count); });
  ASSERT_EQ(static_cast<Index>(read.size()), p.size());
  // Front to back inside each colour round; colour rounds of a slab's parity come one after the other, so the
  // storage is swept once per slab parity: count the backward jumps.
  int backward = 0;
  for (std::size_t k = 1; k < read.size(); ++k) backward += read[k] < read[k - 1] ? 1 : 0;
  EXPECT_LE(backward, bins.colours() - 1) << Shape::name;
}

TEST(TileColouring, SortedParticlesAreReadFrontToBack) {
  check_storage_order<2, LinearHat>({37, 23});
  check_storage_order<2, CubicBSpline>({41, 30});
  check_storage_order<3, LinearHat>({19, 17, 13});
  check_storage_order<3, QuadraticBSpline>({21, 19, 12});
}

/// The visit order does not depend on the thread count: the scatter is recorded as (tile, particle) sequences per
/// node, with 1 and 4 TBB threads.
TEST(TileColouring, EveryNodeSeesItsContributionsInOneOrder) {
  std::mt19937 rng(7);
  const ParticleSet<2> p = scattered<2>(20000, 64, rng);
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Ones(), {64, 64});
  TileBins bins;
  bin_by_tile(p, g, LinearHat::slab_cells, bins);
  auto record = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    std::vector<std::vector<Index>> seen(static_cast<std::size_t>(g.node_count()));
    for_each_tile_coloured(bins, [&](const Index* index, Index count) {
      Stencil<2, LinearHat> st;
      for (Index k = 0; k < count; ++k) {
        st.compute(p.x[index[k]], g);
        for (int a = 0; a < st.count; ++a) seen[static_cast<std::size_t>(st.node[a])].push_back(index[k]);
      }
    });
    return seen;
  };
  EXPECT_EQ(record(1), record(4));
}

}  // namespace
}  // namespace mpm
