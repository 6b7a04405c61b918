// Results do not depend on where the particles sit in memory (docs/distributed.md §1): the particles are sorted
// by (cell, id) before the first step and every sort_interval steps, the scatter visits a tile in that order
// (tile_binning.hpp), and the energy audit sums exactly (exact_sum.hpp), so a scene whose particles are stored
// in another order gives the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>

#include "mpm/core/exact_sum.hpp"
#include "mpm/grid/tile_binning.hpp"
#include "scene_fixture.hpp"

namespace mpm {
namespace {

namespace fs = std::filesystem;

/// Particles at random positions in [0.1, 0.9)^Dim of a unit grid of 10 cells per axis, ids 0 .. n - 1.
template <int Dim>
ParticleSet<Dim> random_particles(int n, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(0.1, 0.9);
  ParticleSet<Dim> p;
  for (int i = 0; i < n; ++i) {
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = u(rng);
    p.add(x, 1, 1e-3);
  }
  return p;
}

/// The ids in the order the scatter visits them, tile by tile.
std::vector<std::uint32_t> visit_order(const TileBins& bins, const std::vector<std::uint32_t>& id) {
  std::vector<std::uint32_t> out;
  for (Index i : bins.order) out.push_back(id[static_cast<std::size_t>(i)]);
  return out;
}

/// order_by_cell sorts by (cell, id) whatever the storage order was: the key strictly increases after it, and
/// the same particles stored in a random order (ids kept) end in the same order, so the tiles are visited
/// in the same order of ids. `n` particles in the 10^Dim cells of the unit box (3000: a few per cell, the
/// insertion sort; 20000 in 2D: hundreds per cell, a shuffled first sort takes the fallback).
template <int Dim>
void check_sort_follows_cell_and_id(int n, int slab_cells) {
  std::mt19937 rng(11);
  const ParticleSet<Dim> p = random_particles<Dim>(n, rng);
  std::array<int, Dim> cells;
  cells.fill(10);
  const GridGeometry<Dim> g(Vec<Dim>::Zero(), Vec<Dim>::Constant(0.1), cells);
  ParticleSet<Dim> sorted = p;
  sorted.gather(order_by_cell(sorted, g, slab_cells));
  const ScatterCellOrder<Dim> place(g, slab_cells);
  for (Index i = 1; i < sorted.size(); ++i)
    ASSERT_LT(scatter_key(place.of(sorted.x[i - 1]), sorted.id[i - 1]),
              scatter_key(place.of(sorted.x[i]), sorted.id[i]))
        << i;
  std::vector<Index> perm(static_cast<std::size_t>(p.size()));
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  ParticleSet<Dim> shuffled = p;
  shuffled.gather(perm);
  shuffled.gather(order_by_cell(shuffled, g, slab_cells));
  EXPECT_EQ(shuffled.id, sorted.id);
  TileBins a, b;
  bin_by_tile(sorted, g, slab_cells, a);
  bin_by_tile(shuffled, g, slab_cells, b);
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(visit_order(a, sorted.id), visit_order(b, shuffled.id));
}

TEST(ScatterOrder, SortFollowsCellThenIdIn2D) { check_sort_follows_cell_and_id<2>(3000, 2); }
TEST(ScatterOrder, SortFollowsCellThenIdIn3D) { check_sort_follows_cell_and_id<3>(3000, 3); }
TEST(ScatterOrder, SortOfAShuffledCrowdFollowsCellThenId) { check_sort_follows_cell_and_id<2>(20000, 1); }

/// The periodic sort keeps its arrays between sorts (CellSortBuffers): sets of other sizes sorted in between, an
/// empty one among them, leave the next sort's order the one fresh arrays give.
TEST(ScatterOrder, KeptBuffersSortLikeFreshOnes) {
  std::mt19937 rng(5);
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Constant(0.1), {10, 10});
  ParticleSet<2> big = random_particles<2>(4000, rng), small = random_particles<2>(300, rng), empty;
  CellSortBuffers buffers;
  for (int round = 0; round < 3; ++round) {
    for (ParticleSet<2>* p : {&big, &empty, &small}) {
      std::vector<Index> perm(static_cast<std::size_t>(p->size()));
      std::iota(perm.begin(), perm.end(), 0);
      std::shuffle(perm.begin(), perm.end(), rng);
      p->gather(perm);
      const std::vector<Index> fresh = order_by_cell(*p, g, 2);
      EXPECT_EQ(order_by_cell(*p, g, 2, buffers), fresh) << "round " << round << ", " << p->size() << " particles";
    }
  }
}

/// After a sort `buffers.sorted` holds every particle's scatter key in the new order (a distributed run keeps them as
/// its scatter_key_field instead of computing them again): with the insertion sort (a few particles per cell) and
/// with the fallback (a shuffled crowd, hundreds per cell).
TEST(ScatterOrder, SortLeavesTheKeysInTheNewOrder) {
  std::mt19937 rng(7);
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Constant(0.1), {10, 10});
  for (const auto& [n, slab_cells] : {std::pair{3000, 2}, std::pair{20000, 1}}) {
    ParticleSet<2> p = random_particles<2>(n, rng);
    std::vector<Index> perm(static_cast<std::size_t>(n));
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), rng);
    p.gather(perm);
    CellSortBuffers buffers;
    p.gather(order_by_cell(p, g, slab_cells, buffers));
    const ScatterCellOrder<2> place(g, slab_cells);
    ASSERT_EQ(buffers.sorted.size(), static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i)
      ASSERT_EQ(buffers.sorted[static_cast<std::size_t>(i)], scatter_key(place.of(p.x[i]), p.id[i]))
          << n << " particles, particle " << i;
  }
}

/// Reordering hands its scratch array to the reordered field, except to a smaller one, which takes a copy (the
/// scratch then stays large enough for the larger set's next sort); either way every value lands where the order
/// says, also when the order leaves particles out (migration).
TEST(ScatterOrder, GatherAfterASmallerOrLargerSetMovesEveryValue) {
  std::mt19937 rng(6);
  ParticleSet<2> big = random_particles<2>(5000, rng), small = random_particles<2>(200, rng);
  const auto check = [](ParticleSet<2>& p, const std::vector<Index>& order) {
    const std::vector<VecU<2>> x(p.x.begin(), p.x.end());
    const std::vector<std::uint32_t> id = p.id;
    p.gather(order);
    ASSERT_EQ(p.size(), static_cast<Index>(order.size()));
    for (std::size_t k = 0; k < order.size(); ++k) {
      ASSERT_EQ(p.id[k], id[static_cast<std::size_t>(order[k])]) << k;
      ASSERT_EQ(p.x[k], x[static_cast<std::size_t>(order[k])]) << k;
    }
  };
  const auto reversed = [](Index n, Index keep) {
    std::vector<Index> o;
    for (Index i = n - 1; i >= 0 && static_cast<Index>(o.size()) < keep; --i) o.push_back(i);
    return o;
  };
  check(big, reversed(big.size(), big.size()));
  check(small, reversed(small.size(), small.size()));  // the scratch is larger: a copy
  check(big, reversed(big.size(), big.size()));        // the scratch is still large enough
  check(small, reversed(small.size(), 150));           // fewer than before (migration), by copy
  check(big, reversed(big.size(), 4000));              // fewer than before, by swap
}

// ---- whole runs ----

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(MPM_BINARY_DIR) / "test_scratch" / "storage_order" / name;
  fs::create_directories(dir);
  return dir;
}

/// A block of particles (2 per cell and axis) with a velocity field that shears and compresses it, written
/// to a CSV particle file in the given order of rows; the ids are the row numbers of the unshuffled file.
template <int Dim>
fs::path write_block(const fs::path& file, bool shuffle, Real h) {
  struct Row {
    Vec<Dim> x, v;
    std::uint32_t id;
  };
  std::vector<Row> rows;
  const int n = Dim == 2 ? 16 : 8;  // particles per axis
  const int count = Dim == 2 ? n * n : n * n * n;
  for (int k = 0; k < count; ++k) {
    Row r;
    int rest = k;
    for (int d = 0; d < Dim; ++d) {
      r.x[d] = 0.3 + (rest % n + 0.5) * h / 2;
      rest /= n;
    }
    r.v[0] = 0.5 * std::sin(7 * r.x[Dim - 1]);
    for (int d = 1; d < Dim; ++d) r.v[d] = -0.3 * r.x[0] + 0.1 * d;
    r.id = static_cast<std::uint32_t>(k);
    rows.push_back(r);
  }
  if (shuffle) {
    std::mt19937 rng(5);
    std::shuffle(rows.begin(), rows.end(), rng);
  }
  std::ofstream out(file);
  out << (Dim == 2 ? "x,y,volume,velocity_x,velocity_y,id\n" : "x,y,z,volume,velocity_x,velocity_y,velocity_z,id\n");
  out.precision(17);
  const Real volume = std::pow(h / 2, Dim);
  for (const Row& r : rows) {
    for (int d = 0; d < Dim; ++d) out << r.x[d] << ",";
    out << volume;
    for (int d = 0; d < Dim; ++d) out << "," << r.v[d];
    out << "," << r.id << "\n";
  }
  return file;
}

template <int Dim>
std::string scene(const fs::path& particles, const std::string& solver, Real h) {
  const std::string dims = Dim == 2 ? "[1, 1]" : "[1, 1, 1]";
  return "dimension: " + std::to_string(Dim) + "\ngrid: {extent: " + dims + ", cell_size: " + std::to_string(h) +
         ", boundary: {" + (Dim == 2 ? "y_min" : "z_min") +
         ": fixed}}\n"
         "materials: {m: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
         "bodies: [{material: m, shape: {particles: " +
         particles.string() + "}}]\nsolver: {" + solver + "}\n";
}

struct Run {
  std::vector<EnergyBalance> energy;  ///< after every step
  std::vector<double> state;          ///< final x, v, stress, F of every particle, by id
};

template <int Dim>
Run run(const std::string& yaml, int steps) {
  auto sim = test::simulation_from_yaml<Dim>(yaml);
  Run r;
  r.energy.push_back(sim->energy());
  for (int s = 0; s < steps; ++s) {
    sim->advance(sim->next_time_step());
    r.energy.push_back(sim->energy());
  }
  const auto& p = sim->bodies().front().particles;
  std::vector<Index> by_id(static_cast<std::size_t>(p.size()));
  std::iota(by_id.begin(), by_id.end(), 0);
  std::sort(by_id.begin(), by_id.end(), [&](Index a, Index b) { return p.id[a] < p.id[b]; });
  for (Index i : by_id) {
    r.state.push_back(p.id[i]);
    for (int d = 0; d < Dim; ++d) r.state.push_back(p.x[i][d]), r.state.push_back(p.v[i][d]);
    for (double c : p.stress[i].c) r.state.push_back(c);
    for (int k = 0; k < Dim * Dim; ++k) r.state.push_back(p.F[i].data()[k]);
  }
  return r;
}

/// Byte-equal: the bit patterns, so that -0 and 0 (and NaN payloads) count as different.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same(const Run& a, const Run& b, const std::string& what) {
  ASSERT_EQ(a.state.size(), b.state.size()) << what;
  for (std::size_t i = 0; i < a.state.size(); ++i)
    ASSERT_TRUE(same_bits(a.state[i], b.state[i]))
        << what << ": state entry " << i << ": " << a.state[i] << " vs " << b.state[i];
  ASSERT_EQ(a.energy.size(), b.energy.size()) << what;
  for (std::size_t s = 0; s < a.energy.size(); ++s) {
    const EnergyBalance &x = a.energy[s], &y = b.energy[s];
    const std::pair<double, double> pairs[] = {
        {x.kinetic, y.kinetic},         {x.strain, y.strain},           {x.gravity, y.gravity},        {x.mass, y.mass},
        {x.momentum[0], y.momentum[0]}, {x.momentum[1], y.momentum[1]}, {x.momentum[2], y.momentum[2]}};
    for (const auto& [u, v] : pairs)
      ASSERT_TRUE(same_bits(u, v)) << what << ": energy row " << s << ": " << u << " vs " << v;
  }
}

template <int Dim>
void check_storage_independence(const std::string& scheme, const std::string& shape) {
  const Real h = Dim == 2 ? 0.05 : 0.1;
  const std::string name = std::to_string(Dim) + "d_" + scheme + "_" + shape;
  const fs::path dir = scratch(name);
  const fs::path plain = write_block<Dim>(dir / "plain.csv", false, h);
  const fs::path shuffled = write_block<Dim>(dir / "shuffled.csv", true, h);
  const std::string solver = "scheme: " + scheme + ", shape_function: " + shape + ", cfl: 0.4, end_time: 10";
  const int steps = Dim == 2 ? 30 : 6;  // 3D: the block moves 0.3 cells (later steps invert particles of the hat USL)
  const Run a = run<Dim>(scene<Dim>(plain, solver, h), steps);
  // the particles stored in another order (ids kept), with the default sort interval and another one
  expect_same(a, run<Dim>(scene<Dim>(shuffled, solver, h), steps), name + ", shuffled rows");
  expect_same(run<Dim>(scene<Dim>(plain, solver + ", sort_interval: 7", h), steps),
              run<Dim>(scene<Dim>(shuffled, solver + ", sort_interval: 7", h), steps), name + ", sorted every 7 steps");
  // the run did something: the block moved and deformed
  EXPECT_GT(std::abs(a.energy.back().strain), 0) << name;
  EXPECT_NE(a.energy.back().kinetic, a.energy.front().kinetic) << name;
}

TEST(StorageOrder, SameBitsForAnyParticleOrder2D) {
  for (const std::string scheme : {"usl", "musl", "usf", "tlmpm"})
    for (const std::string shape : {"linear", "cubic_bspline"}) check_storage_independence<2>(scheme, shape);
}

TEST(StorageOrder, SameBitsForAnyParticleOrder3D) {
  for (const std::string scheme : {"usl", "musl", "usf", "tlmpm"})
    for (const std::string shape : {"linear", "cubic_bspline"}) check_storage_independence<3>(scheme, shape);
}

// ---- exact sums ----

// The energy audit sums one term per particle exactly: the kinetic energy and the momentum of a scene equal,
// bit for bit, the correctly rounded sums of the same terms taken in reverse and in shuffled order, and the
// merge of sums over parts of the particles (what ranks will do).
TEST(ExactEnergy, EqualsTheExactSumInAnyOrder) {
  const Real h = 0.05;
  const fs::path dir = scratch("exact_energy");
  const std::string yaml =
      scene<2>(write_block<2>(dir / "plain.csv", false, h), "scheme: usl, cfl: 0.4, end_time: 10", h);
  auto sim = test::simulation_from_yaml<2>(yaml);
  for (int s = 0; s < 5; ++s) sim->advance(sim->next_time_step());
  const auto& p = sim->bodies().front().particles;
  std::vector<double> kinetic, momentum;
  for (Index i = 0; i < p.size(); ++i) {
    kinetic.push_back(0.5 * p.mass[i] * p.v[i].squaredNorm());
    momentum.push_back(p.mass[i] * p.v[i][0]);
  }
  auto exact = [](const std::vector<double>& terms) {
    ExactSum s;
    for (double t : terms) s += t;
    return s.value();
  };
  const EnergyBalance e = sim->energy();
  std::mt19937 rng(3);
  for (int round = 0; round < 3; ++round) {
    if (round == 1) {
      std::reverse(kinetic.begin(), kinetic.end());
      std::reverse(momentum.begin(), momentum.end());
    } else if (round == 2) {
      std::shuffle(kinetic.begin(), kinetic.end(), rng);
      std::shuffle(momentum.begin(), momentum.end(), rng);
    }
    EXPECT_TRUE(same_bits(e.kinetic, exact(kinetic))) << round;
    EXPECT_TRUE(same_bits(e.momentum[0], exact(momentum))) << round;
    // in three parts, merged
    ExactSum part[3];
    for (std::size_t i = 0; i < kinetic.size(); ++i) part[i % 3] += kinetic[i];
    part[0].merge(part[2]);
    part[0].merge(part[1]);
    EXPECT_TRUE(same_bits(e.kinetic, part[0].value())) << round;
  }
  EXPECT_GT(e.kinetic, 0);
}

}  // namespace
}  // namespace mpm
