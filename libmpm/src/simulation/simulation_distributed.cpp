// The distributed side of Simulation (docs/distributed.md §5): tile ownership, migration of particles,
// the guard's shared report. One process never runs this code.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "mpm/grid/tile_binning.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm {

namespace {

/// The cells of one axis: a coordinate's cell, clamped into the grid before the conversion (so that no value is out
/// of int's range), NaN to cell 0 (the guard has tripped then). Branch-free, and held by value, so that
/// scan_particles' loop keeps it in registers and vectorises.
struct AxisCells {
  Real origin, inv_h, top;
  template <int Dim>
  AxisCells(const GridGeometry<Dim>& g, int d)
      : origin(g.origin[d]), inv_h(g.inv_h[d]), top(static_cast<Real>(g.cells(d) - 1)) {}
  AxisCells() : origin(0), inv_h(0), top(0) {}
  int of(Real x) const {
    Real xi = (x - origin) * inv_h;
    xi = xi > 0 ? xi : 0;  // NaN: 0
    xi = xi < top ? xi : top;
    return static_cast<int>(xi);
  }
};

template <int Dim>
int cell_on_axis(const VecU<Dim>& x, const GridGeometry<Dim>& g, int d) {
  return AxisCells(g, d).of(x[d]);
}

/// The tile holding x (TileGrid's numbering, bin_by_tile's).
template <int Dim>
Index tile_of(const VecU<Dim>& x, const GridGeometry<Dim>& g, const TileGrid& tiles) {
  std::array<int, 3> c{0, 0, 0};
  for (int d = 0; d < Dim; ++d) c[d] = cell_on_axis<Dim>(x, g, d) / tiles.tile_cells[d];
  return tiles.index(c);
}

/// The positions particles are assigned to ranks by: the scheme's (TLMPM: reference) or the current ones.
template <int Dim>
const VecU<Dim>* owner_positions(const Scheme<Dim>& scheme, const ParticleSet<Dim>& p) {
  const VecU<Dim>* x = scheme.ownership_positions(p);
  return x ? x : p.x.data();
}

}  // namespace

template <int Dim>
TileGrid Simulation<Dim>::tile_grid() const {
  const auto [below, above] = scheme_->slab_reach();
  return make_tile_grid(grid_.geometry, scheme_->slab_cells(), below, above);
}

template <int Dim>
std::string Simulation<Dim>::why_not_distributed(int ranks) const {
  if (!scheme_->runs_distributed())
    return fmt::format(
        "scheme '{}' does not run on several ranks yet (distributed runs take usl, musl, usf and tlmpm); "
        "run it in one process",
        scheme_->name());
  for (const auto& m : hooks_.all())
    if (const std::string why = m->why_not_distributed(); !why.empty())
      return fmt::format("module '{}' does not run on several ranks yet ({}); run this scene in one process", m->name(),
                         why);
  const TileGrid tiles = tile_grid();
  if (ranks > tiles.tile_count())
    return fmt::format("{} ranks for {} tiles of the scatter: a rank owns at least one tile; start at most {} ranks",
                       ranks, tiles.tile_count(), tiles.tile_count());
  return {};
}

template <int Dim>
void Simulation<Dim>::distribute(std::shared_ptr<Communicator> comm) {
  if (!comm || comm->size() == 1) return;
  // (a restart restores the state of step N first: its storage order is then the one-process order to distribute)
  if (comm_) throw std::logic_error("Simulation::distribute: call once, before the first step of this process");
  if (const std::string why = why_not_distributed(comm->size()); !why.empty()) throw std::invalid_argument(why);
  const auto& g = grid_.geometry;
  for (auto& b : bodies_) {
    // Before the first sort the storage order is the scene's: the key is the place in it.
    auto& key = b.particles.template add_field<std::uint64_t>(scatter_key_field);
    for (Index i = 0; i < b.particles.size(); ++i) key[i] = static_cast<std::uint64_t>(i);
  }
  comm_ = std::move(comm);
  for (const auto& m : hooks_.all()) m->set_writes_files(comm_->rank() == 0);
  const TileGrid tiles = tile_grid();
  halo_ = std::make_unique<TileHalo>(*comm_, tiles, balanced_owners());
  for (auto& b : bodies_) b.bins.halo = halo_.get();
  // Every rank holds every particle: each keeps its own (the all-to-all of migrate() then moves nothing).
  const int me = comm_->rank();
  for (auto& b : bodies_) {
    auto& p = b.particles;
    const VecU<Dim>* x = owner_positions(*scheme_, p);
    std::vector<Index> keep;
    for (Index i = 0; i < p.size(); ++i)
      if (halo_->owners()[static_cast<std::size_t>(tile_of<Dim>(x[i], g, tiles))] == me) keep.push_back(i);
    p.gather(keep);
  }
  scheme_->particles_redistributed(bodies_, grid_);
  // The cut flags of the first step (TileBins::exchange): its scatters then skip the exchanges of the bodies away
  // from the cuts too, instead of every rank waiting, body after body, for the owner of each body's particles.
  std::vector<double> near(bodies_.size(), 0.0);
  scan_particles(near);
  comm_->max(near);
  near_cut_.assign(bodies_.size(), 0);
  for (std::size_t b = 0; b < bodies_.size(); ++b) near_cut_[b] = near[b] != 0 ? 1 : 0;
  near_cut_known_ = true;
  take_snapshot();
}

template <int Dim>
std::vector<double> Simulation<Dim>::tile_costs() const {
  const auto& g = grid_.geometry;
  const TileGrid tiles = tile_grid();
  std::vector<std::int64_t> count(static_cast<std::size_t>(tiles.tile_count()), 0);
  for (const auto& b : bodies_) {
    const VecU<Dim>* x = owner_positions(*scheme_, b.particles);
    for (Index i = 0; i < b.particles.size(); ++i) ++count[static_cast<std::size_t>(tile_of<Dim>(x[i], g, tiles))];
  }
  if (halo_) comm_->sum(count);  // before distribute() every rank holds every particle
  std::vector<double> cost(count.size());
  for (Index t = 0; t < tiles.tile_count(); ++t) {
    const auto c = tiles.coordinates(t);
    Index cells = 1;
    for (int d = 0; d < Dim; ++d) cells *= std::min(tiles.tile_cells[d], tiles.cells[d] - c[d] * tiles.tile_cells[d]);
    cost[static_cast<std::size_t>(t)] = tile_cost(count[static_cast<std::size_t>(t)], cells);
  }
  return cost;
}

template <int Dim>
std::vector<int> Simulation<Dim>::balanced_owners() const {
  return bisect_tiles(tile_grid(), tile_costs(), comm_->size());
}

template <int Dim>
void Simulation<Dim>::rebalance() {
  const std::vector<double> cost = tile_costs();
  const auto& owner = halo_->owners();
  std::vector<double> load(static_cast<std::size_t>(comm_->size()), 0.0);
  for (std::size_t t = 0; t < cost.size(); ++t) load[static_cast<std::size_t>(owner[t])] += cost[t];
  double total = 0, most = 0;
  for (const double c : load) {
    total += c;
    most = std::max(most, c);
  }
  if (most <= 1.1 * total / comm_->size()) return;
  std::vector<int> balanced = bisect_tiles(halo_->tiles(), cost, comm_->size());
  if (balanced != owner) reassign_tiles(std::move(balanced));
}

template <int Dim>
void Simulation<Dim>::use_owners(const std::vector<int>& owner) {
  // The tiles that write shared nodes change with the owners, and a roll-back or replay (which come through here)
  // moved the particles: every body exchanges in the next step.
  near_cut_known_ = false;
  if (owner == halo_->owners()) return;
  halo_bytes_before_ += halo_->bytes_sent();
  halo_ = std::make_unique<TileHalo>(*comm_, tile_grid(), owner);
  for (auto& b : bodies_) b.bins.halo = halo_.get();
}

template <int Dim>
void Simulation<Dim>::reassign_tiles(std::vector<int> owner) {
  if (!halo_) return;
  use_owners(owner);
  if (comm_->any(migrate())) scheme_->particles_redistributed(bodies_, grid_);
}

template <int Dim>
bool Simulation<Dim>::keeps(const VecU<Dim>& x) const {
  const auto& g = grid_.geometry;
  const HaloPlan& plan = halo_->plan();
  // A rank that owns a box of tiles (the bisection's) keeps a particle exactly when its cell lies in the box's cells
  // on every axis: no lookup of the tile's owner for the particles that stay.
  if (!plan.is_box)
    return halo_->owners()[static_cast<std::size_t>(tile_of<Dim>(x, g, halo_->tiles()))] == comm_->rank();
  bool in = true;
  for (int d = 0; d < Dim; ++d) {
    const int c = cell_on_axis<Dim>(x, g, d);
    in = in && c >= plan.cell_box[d].first && c < plan.cell_box[d].second;
  }
  return in;
}

template <int Dim>
bool Simulation<Dim>::scan_particles(std::span<double> near_cut) const {
  const auto& g = grid_.geometry;
  const HaloPlan& plan = halo_->plan();
  const TileHalo& halo = *halo_;
  const bool movable = scheme_->reorders_particles();
  const int me = comm_->rank();
  std::array<const std::uint32_t*, Dim> flags{};
  std::array<AxisCells, Dim> cells{};
  for (int d = 0; d < Dim; ++d) {
    if (plan.is_box) flags[d] = plan.cell_flags[static_cast<std::size_t>(d)].data();
    cells[d] = AxisCells(g, d);
  }
  // Per particle, bit 1: outside this rank's tiles (keeps() is false), bit 2: in a tile that writes shared nodes.
  // The cells give both; a box of tiles answers with a lookup per axis (HaloPlan::cell_flags), other tile sets by
  // the particle's tile. Blocks without a branch inside (this pass runs after every step over every particle of the
  // rank), the early exit between blocks.
  const auto block_flags = [&](const VecU<Dim>* x, Index first, Index end) {
    unsigned any = 0;
    if (plan.is_box) {  // the geometry in registers: the loop vectorises (~1.4 ns a particle)
      for (Index i = first; i < end; ++i) {
        unsigned f = 0;
        for (int d = 0; d < Dim; ++d) f |= flags[d][cells[d].of(x[i][d])];
        any |= f;
      }
      return any;
    }
    for (Index i = first; i < end; ++i) {
      Index t = 0;  // TileGrid's numbering, bin_by_tile's
      for (int d = 0; d < Dim; ++d) t += halo.tile_term(d, cells[d].of(x[i][d]));
      any |=
          static_cast<unsigned>(halo.owners()[static_cast<std::size_t>(t)] != me) | (halo.writes_shared(t) ? 2u : 0u);
    }
    return any;
  };
  constexpr Index block = 2048;
  bool leaving = false;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const VecU<Dim>* x = owner_positions(*scheme_, bodies_[b].particles);
    bool near = false;
    for (Index i0 = 0, n = bodies_[b].particles.size(); i0 < n; i0 += block) {
      if (near && (leaving || !movable)) break;  // nothing more to learn from this body
      const unsigned any = block_flags(x, i0, std::min(n, i0 + block));
      near = near || any != 0;
      leaving = leaving || (movable && (any & 1u) != 0);
    }
    near_cut[b] = near ? 1 : 0;
  }
  return leaving;
}

template <int Dim>
std::size_t Simulation<Dim>::exchanging_bodies() const {
  if (!halo_) return 0;
  if (!near_cut_known_) return bodies_.size();
  return static_cast<std::size_t>(std::count(near_cut_.begin(), near_cut_.end(), std::uint8_t{1}));
}

template <int Dim>
bool Simulation<Dim>::migrate() {
  const auto& g = grid_.geometry;
  const TileGrid& tiles = halo_->tiles();
  const std::vector<int>& owner = halo_->owners();
  const int me = comm_->rank(), ranks = comm_->size();
  bool moved = false;
  for (auto& b : bodies_) {
    auto& p = b.particles;
    const VecU<Dim>* x = owner_positions(*scheme_, p);
    const Index n = p.size();
    // Most steps no particle leaves: one pass that only reads the positions finds the first that does.
    Index first_leaving = 0;
    while (first_leaving < n && keeps(x[first_leaving])) ++first_leaving;
    std::vector<std::vector<Index>> leaving(static_cast<std::size_t>(ranks));
    std::vector<Index> keep;
    if (first_leaving < n) {
      keep.resize(static_cast<std::size_t>(first_leaving));
      for (Index i = 0; i < first_leaving; ++i) keep[static_cast<std::size_t>(i)] = i;
      keep.reserve(static_cast<std::size_t>(n));
      for (Index i = first_leaving; i < n; ++i) {
        if (keeps(x[i])) {
          keep.push_back(i);
          continue;
        }
        const int to = owner[static_cast<std::size_t>(tile_of<Dim>(x[i], g, tiles))];
        (to == me ? keep : leaving[static_cast<std::size_t>(to)]).push_back(i);
      }
    }
    std::vector<std::vector<std::byte>> out(static_cast<std::size_t>(ranks));
    for (int q = 0; q < ranks; ++q) {
      const auto& which = leaving[static_cast<std::size_t>(q)];
      if (which.empty()) continue;
      auto& buffer = out[static_cast<std::size_t>(q)];
      const auto count = static_cast<std::int64_t>(which.size());
      buffer.resize(sizeof count);
      std::memcpy(buffer.data(), &count, sizeof count);
      p.pack(which, buffer);
    }
    const auto in = comm_->all_to_all(std::move(out));
    bool left = false;
    for (const auto& which : leaving) left = left || !which.empty();
    for (const auto& buffer : in) {
      if (buffer.empty()) continue;
      std::int64_t count = 0;
      std::memcpy(&count, buffer.data(), sizeof count);
      p.append_packed(std::span<const std::byte>(buffer).subspan(sizeof count), count);
    }
    const bool arrived = p.size() != n;
    moved = moved || left || arrived;
    if (!left && !arrived) continue;
    if (!left) {  // every particle stays: the kept ones are [0, n)
      keep.resize(static_cast<std::size_t>(n));
      for (Index i = 0; i < n; ++i) keep[static_cast<std::size_t>(i)] = i;
    }
    // The kept particles are in key order; the arrivals (from several ranks, appended after the n particles of
    // before) are sorted and merged in; the leavers are left out. One gather of every field.
    const auto& key = p.template field<std::uint64_t>(scatter_key_field);
    std::vector<Index> arrivals(static_cast<std::size_t>(p.size() - n));
    for (std::size_t k = 0; k < arrivals.size(); ++k) arrivals[k] = n + static_cast<Index>(k);
    std::sort(arrivals.begin(), arrivals.end(), [&](Index a, Index c) { return key[a] < key[c]; });
    std::vector<Index> order(keep.size() + arrivals.size());
    std::size_t a = 0, c = 0, o = 0;
    while (a < keep.size() || c < arrivals.size()) {
      if (c == arrivals.size() || (a < keep.size() && key[keep[a]] < key[arrivals[c]]))
        order[o++] = keep[a++];
      else
        order[o++] = arrivals[c++];
    }
    p.gather(order);
  }
  return moved;
}

template <int Dim>
void Simulation<Dim>::share_report(StabilityReport& report) const {
  // The lowest rank that found a failing particle speaks for all.
  std::array<double, 1> speaker{report.particle >= 0 ? static_cast<double>(comm_->rank()) : 1e9};
  comm_->min(speaker);
  if (speaker[0] >= 1e9) return;
  const int root = static_cast<int>(speaker[0]);
  std::string text;
  if (comm_->rank() == root)
    text = fmt::format("{}\n{}\n{}\n{}\n{}", report.body, report.particle, report.field, report.face, report.detail);
  std::vector<std::byte> bytes(text.size());
  std::memcpy(bytes.data(), text.data(), text.size());
  comm_->broadcast(bytes, root);
  text.assign(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const auto line = [&](std::size_t& at) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::string part = text.substr(at, end - at);
    at = end + 1;
    return part;
  };
  std::size_t at = 0;
  report.body = line(at);
  report.particle = std::stoll(line(at));
  report.field = line(at);
  report.face = line(at);
  report.detail = text.substr(std::min(at, text.size()));
}

template <int Dim>
void Simulation<Dim>::attach(StepContext<Dim>& ctx) {
  if (!comm_) {
    if (settings_.sparse_grid) ctx.active_tiles = &active_tiles_;
    return;
  }
  ctx.comm = comm_.get();
  ctx.owned_nodes = halo_->owned_nodes();
  ctx.active_nodes = halo_->held_nodes();
  // Sparse tiles on a rank (docs/distributed.md §5.11): the nodes its particles reach, now or at the previous step, and
  // always the reach of its tiles that write shared nodes (what the exchanges write, what other ranks' particles
  // reach of its own nodes). Outside them the rank's grid is zero or never read.
  if (settings_.sparse_grid) {
    active_tiles_.always_mark(halo_->own_shared_tiles());
    ctx.active_tiles = &active_tiles_;
  }
}

#define MPM_SIMULATION_DISTRIBUTED(D)                                     \
  template void Simulation<D>::distribute(std::shared_ptr<Communicator>); \
  template std::string Simulation<D>::why_not_distributed(int) const;     \
  template std::vector<int> Simulation<D>::balanced_owners() const;       \
  template void Simulation<D>::reassign_tiles(std::vector<int>);          \
  template TileGrid Simulation<D>::tile_grid() const;                     \
  template bool Simulation<D>::migrate();                                 \
  template bool Simulation<D>::scan_particles(std::span<double>) const;   \
  template std::size_t Simulation<D>::exchanging_bodies() const;          \
  template bool Simulation<D>::keeps(const VecU<D>&) const;               \
  template std::vector<double> Simulation<D>::tile_costs() const;         \
  template void Simulation<D>::rebalance();                               \
  template void Simulation<D>::use_owners(const std::vector<int>&);       \
  template void Simulation<D>::share_report(StabilityReport&) const;      \
  template void Simulation<D>::attach(StepContext<D>&);
MPM_SIMULATION_DISTRIBUTED(1)
MPM_SIMULATION_DISTRIBUTED(2)
MPM_SIMULATION_DISTRIBUTED(3)
#undef MPM_SIMULATION_DISTRIBUTED

}  // namespace mpm
