// Sparse tiles in one process (active_tiles.hpp): the grid kernels visit only the nodes the particles of
// this step's and the previous step's occupied tiles reach. The claim is that nothing else changes: every case runs
// the same scene twice, sparse (the default) and dense (SimulationSettings::sparse_grid = false), and after every
// step the energy audit, and at the end every particle field of every body and the whole grid (the nodal records
// and velocities the grid output writes, contact's per-body grids included) must be byte-equal. The sparse run must
// also have visited fewer nodes than the grid has, or the comparison would prove nothing. Outside the nodes a step
// visits, the face conditions are not written (no particle reads them there), so velocities are compared on those.
// MemoryFollowsTheParticles: the node arrays hold memory only for the pages of the nodes a step visits.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/state_archive.hpp"
#include "mpm/grid/active_tiles.hpp"
#include "mpm/grid/reserved_pages.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace {

using namespace mpm;

// ---- reached_node_runs against the set it describes, node by node ----

/// Whether a particle of a marked tile can reach node k: the tile's reach holds k on every axis.
bool reached_by_brute_force(const TileGrid& grid, const std::vector<std::uint8_t>& marked, std::array<int, 3> k) {
  for (Index t = 0; t < grid.tile_count(); ++t) {
    if (!marked[static_cast<std::size_t>(t)]) continue;
    const auto c = grid.coordinates(t);
    bool inside = true;
    for (int d = 0; d < grid.dim; ++d) {
      const auto [first, last] = grid.reach(d, c[d]);
      inside = inside && first <= k[d] && k[d] <= last;
    }
    if (inside) return true;
  }
  return false;
}

void expect_runs_are_the_reached_set(const TileGrid& grid, std::mt19937& rng, double fraction) {
  std::vector<std::uint8_t> marked(static_cast<std::size_t>(grid.tile_count()));
  std::bernoulli_distribution mark(fraction);
  for (auto& m : marked) m = mark(rng) ? 1 : 0;
  std::vector<NodeRun> runs;
  reached_node_runs(grid, marked, runs);
  std::vector<std::uint8_t> in_runs(static_cast<std::size_t>(grid.node_count()), 0);
  Index previous_end = -1;
  for (const auto& [first, end] : runs) {
    ASSERT_GT(first, previous_end) << "runs ascending, disjoint and not adjacent (merged)";
    ASSERT_LT(first, end);
    ASSERT_LE(end, grid.node_count());
    for (Index n = first; n < end; ++n) in_runs[static_cast<std::size_t>(n)] = 1;
    previous_end = end;
  }
  std::array<int, 3> k{};
  Index n = 0, differ = 0;
  for (k[2] = 0; k[2] < grid.nodes[2]; ++k[2])
    for (k[1] = 0; k[1] < grid.nodes[1]; ++k[1])
      for (k[0] = 0; k[0] < grid.nodes[0]; ++k[0], ++n)
        differ += (in_runs[static_cast<std::size_t>(n)] != 0) != reached_by_brute_force(grid, marked, k);
  EXPECT_EQ(differ, 0) << "nodes whose membership differs from the brute-force set";
}

TEST(ActiveTiles, RunsHoldExactlyTheNodesTheMarkedTilesReach) {
  std::mt19937 rng(7);
  const GridGeometry<2> g2(Vec<2>::Zero(), Vec<2>::Constant(0.1), {37, 22});  // partial last tiles on both axes
  const GridGeometry<3> g3(Vec<3>::Zero(), Vec<3>::Constant(0.1), {18, 11, 9});
  for (const auto& [slab, below, above] : {std::array<int, 3>{2, 0, 1}, {3, 1, 2}, {5, 2, 2}}) {
    for (const double fraction : {0.0, 0.2, 0.6, 1.0}) {
      expect_runs_are_the_reached_set(make_tile_grid(g2, slab, below, above), rng, fraction);
      expect_runs_are_the_reached_set(make_tile_grid(g3, slab, below, above), rng, fraction);
    }
  }
}

// A distributed rank's tiles that write shared nodes (ActiveTiles::always_mark) are visited at every update, with or
// without particles, and a mark per tile of another grid is refused.
TEST(ActiveTiles, AlwaysMarkedTilesAreVisitedAtEveryUpdate) {
  const GridGeometry<2> g(Vec<2>::Zero(), Vec<2>::Constant(0.1), {37, 22});
  const TileGrid grid = make_tile_grid(g, 2, 0, 1);
  std::vector<std::uint8_t> marks(static_cast<std::size_t>(grid.tile_count()), 0);
  marks[3] = marks[static_cast<std::size_t>(grid.tile_count()) - 1] = 1;
  std::vector<NodeRun> expected;
  reached_node_runs(grid, marks, expected);
  ActiveTiles active;
  active.always_mark(marks);
  for (int update = 0; update < 2; ++update) {
    const NodeRuns nodes = active.update(grid, {});
    ASSERT_FALSE(nodes.all);
    EXPECT_EQ(std::vector<NodeRun>(nodes.runs.begin(), nodes.runs.end()), expected) << "update " << update;
  }
  const std::vector<std::uint8_t> other(marks.size() + 1, 0);
  active.always_mark(other);
  EXPECT_THROW(active.update(grid, {}), std::logic_error);
}

// ---- sparse against dense, whole runs ----

struct Case {
  std::string name;
  std::string file;  ///< under examples/
  int dimension = 2;
  int steps = 40;
  std::string scheme = "musl";
  std::string shape = "linear";
  int coarsen = 1;
  std::string yaml{};  ///< the scene itself, instead of an example
};

/// A block flying across an empty grid: it leaves tiles behind every few steps, so the nodes it left must be cleared
/// exactly as the dense grid clears them.
std::string flying_block(int dimension) {
  if (dimension == 2)
    return "dimension: 2\n"
           "grid: {origin: [0, 0], extent: [1, 1], cell_size: 0.02, "
           "boundary: {x_min: fixed, y_min: {velocity: [\"0.1 * t\", free]}}}\n"
           "materials: {soft: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
           "bodies:\n"
           "  - {name: block, material: soft, shape: {type: box, min: [0.06, 0.1], max: [0.16, 0.2]}, "
           "velocity: [\"3 + 10 * (y - 0.15)\", \"2\"]}\n"
           "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 1}\n";
  return "dimension: 3\n"
         "grid: {origin: [0, 0, 0], extent: [0.6, 0.4, 0.4], cell_size: 0.02}\n"
         "materials: {soft: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
         "bodies:\n"
         "  - {name: block, material: soft, shape: {type: box, min: [0.04, 0.04, 0.04], max: [0.12, 0.12, 0.12]}, "
         "velocity: [\"3\", \"1\", \"1.5\"]}\n"
         "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 1}\n";
}

std::string audit_bytes(double time, const EnergyBalance& e) {
  const double values[] = {time,      e.kinetic,     e.strain,      e.gravity,     e.plastic_work,
                           e.thermal, e.momentum[0], e.momentum[1], e.momentum[2], e.mass};
  return std::string(reinterpret_cast<const char*>(values), sizeof values);
}

/// The first node of `only` whose record differs in bytes, or -1 (so that a failure names a node, not a megabyte of
/// bytes).
template <class Array>
Index first_different_node(const Array& a, const Array& b, NodeRuns only = {}) {
  if (a.size() != b.size()) return 0;
  Index first = -1;
  for_each_node_in_order(static_cast<Index>(a.size()), only, [&](Index n) {
    if (first < 0 && std::memcmp(&a[static_cast<std::size_t>(n)], &b[static_cast<std::size_t>(n)],
                                 sizeof(typename Array::value_type)) != 0)
      first = n;
  });
  return first;
}

template <int Dim>
void expect_sparse_equals_dense(const Case& c) {
  app::register_modules();
  SceneDescription scene = c.yaml.empty() ? load_scene(std::string(MPM_SOURCE_DIR) + "/examples/" + c.file)
                                          : parse_scene(c.yaml, c.name + ".yaml");
  scene.solver.scheme = c.scheme;
  scene.solver.shape_function = c.shape;
  for (int d = 0; d < c.dimension; ++d) {
    scene.grid.cell_size[d] *= c.coarsen;
    scene.grid.cells[d] /= c.coarsen;
  }
  auto sparse = app::build_simulation<Dim>(scene);
  auto dense = app::build_simulation<Dim>(scene);
  dense->use_sparse_grid(false);
  ASSERT_TRUE(sparse->settings().sparse_grid);
  Index fewest = sparse->grid().size();
  for (int s = 0; s < c.steps; ++s) {
    const Real dt = dense->next_time_step();
    ASSERT_EQ(sparse->next_time_step(), dt) << "step " << s + 1;
    dense->advance(dt);
    sparse->advance(dt);
    ASSERT_EQ(audit_bytes(sparse->time(), sparse->energy()), audit_bytes(dense->time(), dense->energy()))
        << "the energy audit after step " << s + 1;
    fewest = std::min(fewest, sparse->active_tiles().nodes().count(sparse->grid().size()));
  }
  EXPECT_LT(fewest, sparse->grid().size()) << "the sparse run visited every node at every step: nothing was tested";
  for (std::size_t b = 0; b < dense->bodies().size(); ++b) {
    const auto& p = dense->bodies()[b].particles;
    const auto& q = sparse->bodies()[b].particles;
    ASSERT_EQ(p.size(), q.size());
    std::vector<Index> all(static_cast<std::size_t>(p.size()));
    for (Index i = 0; i < p.size(); ++i) all[static_cast<std::size_t>(i)] = i;
    for (const auto& field : p.field_layout()) {
      std::vector<std::byte> a, b2;
      p.pack_field(field.name, all, a);
      q.pack_field(field.name, all, b2);
      EXPECT_TRUE(a == b2) << "body " << b << " field " << field.name;
    }
  }
  EXPECT_EQ(first_different_node(sparse->grid().node, dense->grid().node), -1) << "nodal mass, momentum and force";
  // Velocities where the last step's kernels wrote them: outside, the dense grid also holds the face conditions'
  // values, which the sparse grid writes only where a particle can read them (GridBoundary::apply).
  const NodeRuns visited = sparse->active_tiles().nodes();
  EXPECT_EQ(first_different_node(sparse->grid().velocity, dense->grid().velocity, visited), -1) << "nodal velocities";
  for (std::size_t b = 0; b < dense->bodies().size(); ++b)
    if (const Grid<Dim>* own = dense->bodies()[b].separate_grid) {
      const Grid<Dim>* mine = sparse->bodies()[b].separate_grid;
      ASSERT_NE(mine, nullptr);
      EXPECT_EQ(first_different_node(mine->node, own->node), -1) << "body " << b << "'s own grid (contact)";
      EXPECT_EQ(first_different_node(mine->velocity, own->velocity, visited), -1)
          << "body " << b << "'s own grid velocities";
    }
}

class SparseGrid : public ::testing::TestWithParam<Case> {};

TEST_P(SparseGrid, GivesTheBitsOfTheDenseGrid) {
  const Case& c = GetParam();
  if (c.dimension == 2)
    expect_sparse_equals_dense<2>(c);
  else
    expect_sparse_equals_dense<3>(c);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SparseGrid,
    ::testing::Values(Case{"dam_break_musl_linear", "12_dam_break/scene.yaml", 2, 40, "musl", "linear"},
                      Case{"dam_break_usl_gimp", "12_dam_break/scene.yaml", 2, 30, "usl", "gimp"},
                      Case{"two_disks_usf_quadratic", "02_two_disks/scene.yaml", 2, 40, "usf", "quadratic_bspline"},
                      Case{"two_disks_usl_cpdi_q4", "02_two_disks/scene.yaml", 2, 40, "usl", "cpdi_q4"},
                      Case{"ring_crush_contact_gimp", "09_ring_crush/scene.yaml", 2, 30, "musl", "gimp"},
                      Case{"fsi_obstacle_contact", "14_fsi_obstacle/contact.yaml", 2, 30, "musl", "linear"},
                      Case{"taylor_anvil_3d_musl_linear", "05_taylor_anvil/musl.yaml", 3, 5, "musl", "linear", 1},
                      Case{"flying_block_musl_linear", "", 2, 120, "musl", "linear", 1, flying_block(2)},
                      Case{"flying_block_usf_cubic", "", 2, 120, "usf", "cubic_bspline", 1, flying_block(2)},
                      Case{"flying_block_usl_gimp", "", 2, 120, "usl", "gimp", 1, flying_block(2)},
                      Case{"flying_block_3d_usl_linear", "", 3, 80, "usl", "linear", 1, flying_block(3)},
                      Case{"thermal_taylor_3d", "11_thermal_taylor/musl.yaml", 3, 5, "musl", "linear", 1}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

// ---- memory follows the particles (reserved_pages.hpp) ----

TEST(ReservedPages, UnwrittenPagesCostNothingAndReleasedPagesReadAsZeros) {
  const std::size_t page = page_bytes();
  NodeArray<NodeRecord<3>> a(200000);  // 11.2 MB of address space
  const std::size_t bytes = sizeof(NodeRecord<3>) * a.size();
  EXPECT_EQ(resident_bytes(a.data(), bytes), 0u) << "a new array must not touch its pages";
  a[100000].mass = 2.5;
  EXPECT_EQ(resident_bytes(a.data(), bytes), page) << "one write, one page";
  release_pages(a.data(), bytes);
  EXPECT_EQ(resident_bytes(a.data(), bytes), 0u);
  EXPECT_EQ(a[100000].mass, 0.0) << "a released page reads as zeros";
  // Reading maps the system's shared zero page (no memory, though mincore counts it): a fresh array reads as zeros.
  EXPECT_EQ(a[123456].mass, 0.0);
  EXPECT_EQ(a[123456].force[2], 0.0);
}

/// The pages of `array` that hold a node of `runs`.
template <class Array>
std::size_t pages_of(const Array& array, NodeRuns runs) {
  const std::size_t page = page_bytes();
  const auto base = reinterpret_cast<std::uintptr_t>(array.data());
  const std::size_t record = sizeof(typename Array::value_type);
  std::size_t count = 0, last = static_cast<std::size_t>(-1);
  for (const auto& [first, end] : runs.runs) {
    std::size_t p0 = (base + static_cast<std::size_t>(first) * record) / page;
    const std::size_t p1 = (base + static_cast<std::size_t>(end) * record - 1) / page;
    if (p0 == last) ++p0;
    if (p1 >= p0) count += p1 - p0 + 1;
    last = p1;
  }
  return count * page;
}

// A block crossing a 3D grid with held faces on every side: at every step the node arrays have memory for the pages
// of the visited nodes and no more (a write of the face conditions outside them, or pages of the stretches left
// behind kept, breaks the bound), far less than the dense grid, whose pages are all in memory.
SceneDescription flying_block_between_walls() {
  app::register_modules();
  return parse_scene(
      "dimension: 3\n"
      "grid: {origin: [0, 0, 0], extent: [1.2, 0.4, 0.4], cell_size: 0.02, boundary: {x_min: slip, x_max: slip, "
      "y_min: slip, y_max: slip, z_min: fixed, z_max: slip}}\n"
      "materials: {soft: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e4, poisson_ratio: 0.3}}\n"
      "bodies:\n"
      "  - {name: block, material: soft, shape: {type: box, min: [0.04, 0.04, 0.04], max: [0.12, 0.12, 0.12]}, "
      "velocity: [\"3\", \"1\", \"1.5\"]}\n"
      "solver: {scheme: musl, shape_function: linear, cfl: 0.5, end_time: 1}\n",
      "flying_block_walls.yaml");
}

/// Pages of the node arrays in memory, at most those of the nodes the last step visited.
void expect_pages_of_the_visited_nodes(const Simulation<3>& sim, int step) {
  const NodeRuns visited = sim.active_tiles().nodes();
  ASSERT_FALSE(visited.all) << "step " << step;
  const auto& g = sim.grid();
  ASSERT_LE(g.resident_bytes(), pages_of(g.node, visited) + pages_of(g.velocity, visited))
      << "step " << step << ": pages in memory beyond the visited nodes'";
}

TEST(SparseGrid, MemoryFollowsTheParticles) {
  const SceneDescription scene = flying_block_between_walls();
  auto sparse = app::build_simulation<3>(scene);
  auto dense = app::build_simulation<3>(scene);
  dense->use_sparse_grid(false);
  const auto& g = sparse->grid();
  const std::size_t whole = sizeof(NodeRecord<3>) * g.node.size() + sizeof(NodeVelocity<3>) * g.velocity.size();
  EXPECT_EQ(g.resident_bytes(), 0u) << "before the first step";
  std::size_t most = 0;
  for (int s = 0; s < 100; ++s) {
    const Real dt = dense->next_time_step();
    dense->advance(dt);
    sparse->advance(dt);
    expect_pages_of_the_visited_nodes(*sparse, s + 1);
    if (HasFatalFailure()) return;
    most = std::max(most, g.resident_bytes());
  }
  EXPECT_GT(sparse->bodies()[0].particles.x[0][0], 0.4) << "the block crossed the grid";
  EXPECT_GE(dense->grid().resident_bytes(), whole) << "the dense grid writes every page";
  // A row of 61 nodes along x is about one page, so the pages follow the rows the block's tiles reach: about 27%.
  EXPECT_LT(most, whole / 3) << "most bytes in memory at a step: " << most << " of " << whole;
  std::cout << "node arrays: " << whole << " bytes, at most " << most << " in memory (sparse)\n";
  EXPECT_EQ(sparse->bodies()[0].particles.x, dense->bodies()[0].particles.x) << "positions differ from the dense run";
}

// A restored checkpoint zeroes the grid (Grid::clear) instead of stepping dense once: the simulation it is restored
// into has written its grid before, yet no page beyond the visited nodes' comes into memory, and the run continues
// with the bits of the uninterrupted one.
TEST(SparseGrid, ARestoredStateStepsSparse) {
  const SceneDescription scene = flying_block_between_walls();
  auto run = app::build_simulation<3>(scene);
  for (int s = 0; s < 40; ++s) run->advance(run->next_time_step());
  StateArchive archive;
  run->save_state(archive);
  auto restored = app::build_simulation<3>(scene);
  for (int s = 0; s < 60; ++s) restored->advance(restored->next_time_step());  // writes its grid elsewhere
  restored->restore_state(archive);
  EXPECT_LE(restored->grid().resident_bytes(), 4 * page_bytes()) << "the ends of the two arrays at most";
  for (int s = 0; s < 40; ++s) {
    const Real dt = run->next_time_step();
    ASSERT_EQ(restored->next_time_step(), dt) << "step " << s + 1;
    run->advance(dt);
    restored->advance(dt);
    expect_pages_of_the_visited_nodes(*restored, s + 1);
    if (HasFatalFailure()) return;
  }
  EXPECT_EQ(restored->bodies()[0].particles.x, run->bodies()[0].particles.x) << "positions";
  EXPECT_EQ(restored->bodies()[0].particles.v, run->bodies()[0].particles.v) << "velocities";
}

}  // namespace
