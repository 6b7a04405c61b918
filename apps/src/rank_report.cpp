#include "mpm/app/rank_report.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mpm/app/memory_budget.hpp"
#include "mpm/parallel/tile_halo.hpp"
#include "mpm/schemes/scheme_registry.hpp"

namespace mpm::app {

namespace {

/// Ranks up to this many get a line each; more get the spread (smallest, mean, largest).
constexpr int listed_ranks = 16;

std::string tile_shape(const TileGrid& t) {
  std::string cells, tiles;
  for (int d = 0; d < t.dim; ++d) {
    cells += (d ? " x " : "") + std::to_string(t.tile_cells[d]);
    tiles += (d ? " x " : "") + std::to_string(t.tiles[d]);
  }
  return fmt::format("{} tiles of {} cells ({})", t.tile_count(), cells, tiles);
}

}  // namespace

template <int Dim>
void rank_report(const SceneDescription& scene, const Simulation<Dim>& sim, int ranks, std::ostream& out,
                 std::ostream& log) {
  const TileGrid tiles = sim.tile_grid();
  if (ranks > tiles.tile_count())
    throw RankCountError(
        fmt::format("--ranks {}: more ranks than the {} of {}; a rank owns whole tiles, so at most {} ranks "
                    "(docs/distributed.md §5.1)",
                    ranks, tile_shape(tiles), scene.file, tiles.tile_count()));
  const std::vector<double> cost = sim.tile_costs();
  const std::vector<int> owner = bisect_tiles(tiles, cost, ranks);
  // Particles per tile, from the costs' particle term (tile_cost: particles + a tenth of the tile's cells).
  std::vector<std::int64_t> particles(cost.size(), 0);
  Index occupied = 0;
  {
    const auto& g = sim.grid().geometry;
    for (const auto& body : sim.bodies())
      for (const auto& x : body.particles.x) {
        std::array<int, 3> c{0, 0, 0};
        for (int d = 0; d < Dim; ++d)
          c[d] =
              std::clamp(static_cast<int>((x[d] - g.origin[d]) * g.inv_h[d]), 0, g.cells(d) - 1) / tiles.tile_cells[d];
        ++particles[static_cast<std::size_t>(tiles.index(c))];
      }
    for (const std::int64_t n : particles) occupied += n > 0;
  }
  const SchemeTraits& scheme = scheme_of(scene.solver).traits;
  const auto scatters = static_cast<std::size_t>(scheme.scatters_per_step);
  const std::size_t bytes_per_node = sizeof(NodeRecord<Dim>) * scatters * sim.bodies().size();
  struct Share {
    std::int64_t particles = 0;
    Index tiles = 0;
    double cost = 0;
    std::size_t messages = 0;
  };
  std::vector<Share> share(static_cast<std::size_t>(ranks));
  for (std::size_t t = 0; t < owner.size(); ++t) {
    Share& s = share[static_cast<std::size_t>(owner[t])];
    s.particles += particles[t];
    ++s.tiles;
    s.cost += cost[t];
  }
  std::size_t halo = 0;
  for (int r = 0; r < ranks; ++r) {
    const HaloPlan plan = plan_halo(tiles, owner, r);
    halo += plan.bytes_per_scatter(bytes_per_node);
    share[static_cast<std::size_t>(r)].messages = plan.sends.size();
  }
  double total = 0, most = 0;
  for (const Share& s : share) {
    total += s.cost;
    most = std::max(most, s.cost);
  }
  const double mean = total / ranks;
  fmt::print(out, "ranks: {} on {}, each rank a box of tiles (recursive bisection); {} tiles hold particles\n", ranks,
             tile_shape(tiles), occupied);
  if (!scheme.runs_distributed)
    fmt::print(log,
               "warning: scheme {} runs in one process only; the shares listed are what a distributed scheme "
               "would get\n",
               scene.solver.scheme_name());
  if (ranks <= listed_ranks) {
    fmt::print(out, "  rank  particles  tiles  cost / mean  messages per scatter\n");
    for (int r = 0; r < ranks; ++r) {
      const Share& s = share[static_cast<std::size_t>(r)];
      fmt::print(out, "  {:>4}  {:>9}  {:>5}  {:>11.3f}  {:>20}\n", r, s.particles, s.tiles,
                 mean > 0 ? s.cost / mean : 1.0, s.messages);
    }
  } else {
    const auto [least, largest] = std::minmax_element(
        share.begin(), share.end(), [](const Share& a, const Share& b) { return a.particles < b.particles; });
    fmt::print(out, "  particles per rank: {} to {} (mean {:.1f})\n", least->particles, largest->particles,
               static_cast<double>(sim.particle_count()) / ranks);
  }
  fmt::print(out, "  most loaded rank: {:.3f} x the mean cost (particles + a tenth of a tile's cells)\n",
             mean > 0 ? most / mean : 1.0);
  if (ranks > occupied)
    fmt::print(log, "warning: only {} tiles hold particles: {} of the {} ranks would start without any\n", occupied,
               ranks - occupied, ranks);
  fmt::print(out, "  at most {} ranks get particles (one occupied tile each)\n", occupied);
  if (!scheme.runs_distributed) {
    fmt::print(out, "halo: none (scheme {} runs in one process)\n", scene.solver.scheme_name());
    return;
  }
  fmt::print(out, "halo: {} per step ({} scatter(s) x {} bod{} x {} B per ghost node and array, every rank's sends)\n",
             format_bytes(static_cast<double>(halo)), scatters, sim.bodies().size(),
             sim.bodies().size() == 1 ? "y" : "ies", sizeof(NodeRecord<Dim>));
}

template void rank_report<1>(const SceneDescription&, const Simulation<1>&, int, std::ostream&, std::ostream&);
template void rank_report<2>(const SceneDescription&, const Simulation<2>&, int, std::ostream&, std::ostream&);
template void rank_report<3>(const SceneDescription&, const Simulation<3>&, int, std::ostream&, std::ostream&);

}  // namespace mpm::app
