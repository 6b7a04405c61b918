#include "mpm/app/rank_report.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "mpm/memory_budget.hpp"
#include "mpm/shape/shape_functions.hpp"
#include "mpm/slab_halo.hpp"
#include "mpm/tile_binning.hpp"
#include "mpm/tiling.hpp"

namespace mpm::app {

namespace {

/// Ranks up to this many get a line each; more get the spread (smallest, mean, largest).
constexpr int listed_ranks = 16;

template <int Dim>
std::string tile_shape(const Tiling<Dim>& t) {
  std::string cells, tiles;
  for (int d = 0; d < Dim; ++d) {
    cells += (d ? " x " : "") + std::to_string(t.tile_cells);
    tiles += (d ? " x " : "") + std::to_string(t.tiles[d]);
  }
  return fmt::format("{} tiles of {} cells ({})", t.tile_count(), cells, tiles);
}

/// What `mpirun -np N mpm run` does today (docs/distributed.md §5): runs of slabs of the last axis, the particles
/// of each rank, and the ghost-node bytes a step sends (the halo model SlabHalo::model_bytes_per_scatter counts).
template <int Dim>
void slab_report(const SceneDescription& scene, const Simulation<Dim>& sim, int ranks, int T, int below, int above,
                 std::ostream& out) {
  const GridGeometry<Dim>& g = sim.grid().geometry;
  const int slabs = (g.cells(Dim - 1) + T - 1) / T;
  const char* axis = Dim == 1 ? "x" : Dim == 2 ? "y" : "z";
  if (ranks > slabs) {
    fmt::print(out,
               "mpirun today: {} slabs of {} cells along {}: `mpirun -np {}` would be refused (at most {} ranks)\n",
               slabs, T, axis, ranks, slabs);
    return;
  }
  std::vector<std::int64_t> count(slabs, 0);
  for (const auto& body : sim.bodies())
    for (const auto& x : body.particles.x) {
      const Real xi = (x[Dim - 1] - g.origin[Dim - 1]) * g.inv_h[Dim - 1];
      ++count[std::clamp(static_cast<int>(xi), 0, g.cells(Dim - 1) - 1) / T];
    }
  std::vector<double> cost(slabs);
  for (int s = 0; s < slabs; ++s) cost[s] = slab_cost(count[s], g.stride[Dim - 1], T);
  const std::vector<int> first = cut_slabs(cost, ranks);
  const std::string scheme = scene.solver.scheme_name();
  const int scatters = scheme == "usl" ? 1 : 2;
  std::size_t halo = 0;  // both directions of every rank boundary, per step
  for (int r = 1; r < ranks; ++r) {
    const int lo = std::max(0, first[r] * T - below), hi = std::min(g.nodes[Dim - 1] - 1, first[r] * T - 1 + above);
    if (hi >= lo) halo += 2 * static_cast<std::size_t>(hi - lo + 1) * static_cast<std::size_t>(g.stride[Dim - 1]);
  }
  halo *= sizeof(NodeRecord<Dim>) * scatters * sim.bodies().size();
  fmt::print(out, "mpirun today: {} slabs of {} cells along {} (at most {} ranks)\n", slabs, T, axis, slabs);
  if (ranks <= listed_ranks) {
    fmt::print(out, "  rank  slabs      particles\n");
    for (int r = 0; r < ranks; ++r) {
      std::int64_t n = 0;
      for (int s = first[r]; s < first[r + 1]; ++s) n += count[s];
      fmt::print(out, "  {:>4}  {:>4}-{:<4}  {:>9}\n", r, first[r], first[r + 1] - 1, n);
    }
  }
  fmt::print(out, "  halo: {} per step ({} scatter(s) x {} bod{} x 2 messages per rank boundary)\n",
             format_bytes(static_cast<double>(halo)), scatters, sim.bodies().size(),
             sim.bodies().size() == 1 ? "y" : "ies");
}

}  // namespace

template <int Dim>
void rank_report(const SceneDescription& scene, const Simulation<Dim>& sim, int ranks, std::ostream& out) {
  int support = 2, slab_cells = 2, reach_below = 0, reach_above = 1;
  dispatch_shape(scene.solver.shape_function, [&]<class Shape>() {
    support = Shape::support;
    slab_cells = Shape::slab_cells;
    reach_below = Shape::slab_reach_below;
    reach_above = Shape::slab_reach_above;
  });
  const GridGeometry<Dim>& g = sim.grid().geometry;
  const Tiling<Dim> tiling = make_tiling(g, slab_cells);
  if (ranks > tiling.tile_count())
    throw RankCountError(
        fmt::format("--ranks {}: more ranks than the {} of {}; a rank owns whole tiles, so at most {} "
                    "ranks (docs/distributed.md §2)",
                    ranks, tile_shape(tiling), scene.file, tiling.tile_count()));
  std::vector<Index> cells;
  cells.reserve(sim.particle_count());
  for (const auto& body : sim.bodies())
    for (const auto& x : body.particles.x) cells.push_back(cell_index<Dim>(x, g));
  const DecompositionModel m = model_decomposition(tiling, cells, support, ranks);
  const int doubles = halo_doubles_per_node(Dim, scene.solver.scheme_name());
  fmt::print(out, "ranks: {} on {}; {} hold particles, {} are in reach of one\n", ranks, tile_shape(tiling),
             m.occupied_tiles, m.active_tiles);
  const double mean_cost = [&] {
    double c = 0;
    for (const auto& r : m.ranks) c += r.cost;
    return c / ranks;
  }();
  if (ranks <= listed_ranks) {
    fmt::print(out, "  rank  particles  tiles  ghost nodes  cost / mean\n");
    for (int r = 0; r < ranks; ++r)
      fmt::print(out, "  {:>4}  {:>9}  {:>5}  {:>11}  {:>11.3f}\n", r, m.ranks[r].particles, m.ranks[r].tiles,
                 m.ranks[r].ghost_nodes, mean_cost > 0 ? m.ranks[r].cost / mean_cost : 1.0);
  } else {
    const auto [least, most] = std::minmax_element(
        m.ranks.begin(), m.ranks.end(), [](const auto& a, const auto& b) { return a.particles < b.particles; });
    fmt::print(out, "  particles per rank: {} to {} (mean {:.1f})\n", least->particles, most->particles,
               static_cast<double>(sim.particle_count()) / ranks);
  }
  fmt::print(out, "  most loaded rank: {:.3f} x the mean cost (particles x {}^{} stencil nodes + nodes in reach)\n",
             m.imbalance(), support, Dim);
  if (ranks > m.occupied_tiles)
    fmt::print(out, "warning: only {} tiles hold particles: {} of the {} ranks would start without any\n",
               m.occupied_tiles, ranks - m.occupied_tiles, ranks);
  fmt::print(out, "  at most {} ranks get particles (one occupied tile each)\n", m.occupied_tiles);
  fmt::print(out,
             "halo: {} ghost nodes, {} per step ({} doubles each way per ghost node: the nodal fields {} scatters)\n",
             m.ghost_nodes(), format_bytes(2.0 * 8.0 * doubles * static_cast<double>(m.ghost_nodes())), doubles,
             scene.solver.scheme_name());
  slab_report(scene, sim, ranks, slab_cells, reach_below, reach_above, out);
}

template void rank_report<1>(const SceneDescription&, const Simulation<1>&, int, std::ostream&);
template void rank_report<2>(const SceneDescription&, const Simulation<2>&, int, std::ostream&);
template void rank_report<3>(const SceneDescription&, const Simulation<3>&, int, std::ostream&);

}  // namespace mpm::app
