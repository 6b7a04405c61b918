// The distributed side of Simulation (issue 18, docs/distributed.md §4): slab ownership, migration of particles,
// the guard's shared report. One process never runs this code.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "mpm/simulation.hpp"
#include "mpm/tile_binning.hpp"

namespace mpm {

bool slab_baseline_requested();  // slab_halo.cpp: MPM_DEBUG_SLAB_BASELINE

template <int Dim>
void set_scatter_keys(ParticleSet<Dim>& p, const GridGeometry<Dim>& g, int slab_cells) {
  auto& key = p.template field<std::uint64_t>(scatter_key_field);
  const ScatterCellOrder<Dim> place(g, slab_cells);
  for (Index i = 0; i < p.size(); ++i) key[i] = scatter_key(place.of(p.x[i]), p.id[i]);
}

namespace {

/// The slab of the cell holding x on the last axis (clamped into the grid; NaN: slab 0, the guard has tripped).
template <int Dim>
int slab_of(const VecU<Dim>& x, const GridGeometry<Dim>& g, int slab_cells) {
  constexpr int axis = Dim - 1;
  const Real xi = (x[axis] - g.origin[axis]) * g.inv_h[axis];
  const int cell = std::isfinite(xi) ? std::clamp(static_cast<int>(xi), 0, g.cells(axis) - 1) : 0;
  return cell / slab_cells;
}

/// The positions particles are assigned to ranks by: the scheme's (TLMPM: reference) or the current ones.
template <int Dim>
const VecU<Dim>* owner_positions(const Scheme<Dim>& scheme, const ParticleSet<Dim>& p) {
  const VecU<Dim>* x = scheme.ownership_positions(p);
  return x ? x : p.x.data();
}

}  // namespace

template <int Dim>
std::string Simulation<Dim>::why_not_distributed(int ranks) const {
  if (!scheme_->runs_distributed())
    return fmt::format(
        "scheme '{}' does not run on several ranks yet (distributed runs take usl, musl, usf and tlmpm, issue 18); "
        "run it in one process",
        scheme_->name());
  for (const auto& m : hooks_.all())
    if (const std::string why = m->why_not_distributed(); !why.empty())
      return fmt::format("module '{}' does not run on several ranks yet ({}); run this scene in one process", m->name(),
                         why);
  const auto& g = grid_.geometry;
  const int T = scheme_->slab_cells();
  const int slabs = (g.cells(Dim - 1) + T - 1) / T;
  if (ranks > slabs)
    return fmt::format(
        "{} ranks for {} slabs of {} cells along the grid's last axis: a rank owns at least one slab; start at most "
        "{} ranks",
        ranks, slabs, T, slabs);
  return {};
}

template <int Dim>
void Simulation<Dim>::distribute(std::shared_ptr<Communicator> comm) {
  if (!comm || comm->size() == 1) return;
  // (a restart restores the state of step N first: its storage order is then the one-process order to distribute)
  if (comm_) throw std::logic_error("Simulation::distribute: call once, before the first step of this process");
  if (const std::string why = why_not_distributed(comm->size()); !why.empty()) throw std::invalid_argument(why);
  const auto& g = grid_.geometry;
  const int T = scheme_->slab_cells();
  for (auto& b : bodies_) {
    // Before the first sort the storage order is the scene's: the key is the place in it.
    auto& key = b.particles.template add_field<std::uint64_t>(scatter_key_field);
    for (Index i = 0; i < b.particles.size(); ++i) key[i] = static_cast<std::uint64_t>(i);
  }
  comm_ = std::move(comm);
  for (const auto& m : hooks_.all()) m->set_writes_files(comm_->rank() == 0);
  const auto [below, above] = scheme_->slab_reach();
  halo_ = std::make_unique<SlabHalo>(*comm_, balanced_slabs(), T, below, above, g.nodes[Dim - 1], g.stride[Dim - 1]);
  for (auto& b : bodies_) b.bins.halo = halo_.get();
  // Every rank holds every particle: each keeps its own (the all-to-all of migrate() then moves nothing).
  const int me = comm_->rank();
  for (auto& b : bodies_) {
    auto& p = b.particles;
    const VecU<Dim>* x = owner_positions(*scheme_, p);
    std::vector<Index> keep;
    for (Index i = 0; i < p.size(); ++i)
      if (halo_->owner_of_slab(slab_of<Dim>(x[i], g, T)) == me) keep.push_back(i);
    p.gather(keep);
  }
  scheme_->particles_redistributed(bodies_, grid_);
  take_snapshot();
}

template <int Dim>
std::vector<double> Simulation<Dim>::slab_costs() const {
  const auto& g = grid_.geometry;
  const int T = scheme_->slab_cells();
  const int slabs = (g.cells(Dim - 1) + T - 1) / T;
  std::vector<std::int64_t> count(slabs, 0);
  for (const auto& b : bodies_) {
    const VecU<Dim>* x = owner_positions(*scheme_, b.particles);
    for (Index i = 0; i < b.particles.size(); ++i) ++count[slab_of<Dim>(x[i], g, T)];
  }
  if (halo_) comm_->sum(count);  // before distribute() every rank holds every particle
  std::vector<double> cost(slabs);
  for (int s = 0; s < slabs; ++s) cost[s] = slab_cost(count[s], g.stride[Dim - 1], T);
  return cost;
}

template <int Dim>
std::vector<int> Simulation<Dim>::balanced_slabs() const {
  return cut_slabs(slab_costs(), comm_->size());
}

template <int Dim>
void Simulation<Dim>::rebalance() {
  const std::vector<double> cost = slab_costs();
  const auto& first = halo_->first_slab();
  double total = 0, most = 0;
  for (int r = 0; r + 1 < static_cast<int>(first.size()); ++r) {
    double c = 0;
    for (int s = first[r]; s < first[r + 1]; ++s) c += cost[s];
    total += c;
    most = std::max(most, c);
  }
  const double mean = total / comm_->size();
  if (most <= 1.1 * mean) return;
  std::vector<int> balanced = cut_slabs(cost, comm_->size());
  if (balanced != first) reassign_slabs(std::move(balanced));
}

template <int Dim>
void Simulation<Dim>::use_slabs(const std::vector<int>& first_slab) {
  if (first_slab == halo_->first_slab()) return;
  halo_bytes_before_ += halo_->bytes_sent();
  const auto [below, above] = scheme_->slab_reach();
  const auto& g = grid_.geometry;
  halo_ = std::make_unique<SlabHalo>(*comm_, first_slab, scheme_->slab_cells(), below, above, g.nodes[Dim - 1],
                                     g.stride[Dim - 1]);
  for (auto& b : bodies_) b.bins.halo = halo_.get();
}

template <int Dim>
void Simulation<Dim>::reassign_slabs(std::vector<int> first_slab) {
  if (!halo_) return;
  use_slabs(first_slab);
  if (comm_->any(migrate())) scheme_->particles_redistributed(bodies_, grid_);
}

template <int Dim>
bool Simulation<Dim>::migrate() {
  const auto& g = grid_.geometry;
  const int T = scheme_->slab_cells();
  const int me = comm_->rank(), ranks = comm_->size();
  // This rank's cells along the last axis: slab_of(x) is one of its slabs exactly when the cell slab_of computes
  // lies in [first_cell, end_cell), so the scan needs no search over the slabs' owners.
  const int first_cell = halo_->first_slab()[static_cast<std::size_t>(me)] * T;
  const int end_cell = halo_->first_slab()[static_cast<std::size_t>(me) + 1] * T;
  const auto stays = [&](const VecU<Dim>& x) {
    const int cell = slab_of<Dim>(x, g, 1);
    return cell >= first_cell && cell < end_cell;
  };
  bool moved = false;
  for (auto& b : bodies_) {
    auto& p = b.particles;
    const VecU<Dim>* x = owner_positions(*scheme_, p);
    const Index n = p.size();
    // Most steps no particle leaves: one pass that only reads the positions finds the first that does.
    Index first_leaving = 0;
    while (first_leaving < n && stays(x[first_leaving])) ++first_leaving;
    if (slab_baseline_requested()) first_leaving = 0;  // the scan of before: every particle's owner looked up
    std::vector<std::vector<Index>> leaving(static_cast<std::size_t>(ranks));
    std::vector<Index> keep;
    if (first_leaving < n) {
      keep.resize(static_cast<std::size_t>(first_leaving));
      for (Index i = 0; i < first_leaving; ++i) keep[static_cast<std::size_t>(i)] = i;
      keep.reserve(static_cast<std::size_t>(n));
      for (Index i = first_leaving; i < n; ++i) {
        if (!slab_baseline_requested() && stays(x[i])) {
          keep.push_back(i);
          continue;
        }
        const int owner = halo_->owner_of_slab(slab_of<Dim>(x[i], g, T));
        (owner == me ? keep : leaving[static_cast<std::size_t>(owner)]).push_back(i);
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
    text = fmt::format("{}\n{}\n{}\n{}", report.body, report.particle, report.field, report.detail);
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
  report.detail = text.substr(std::min(at, text.size()));
}

template <int Dim>
void Simulation<Dim>::attach(StepContext<Dim>& ctx) const {
  if (!comm_) return;
  ctx.comm = comm_.get();
  ctx.owned_nodes = halo_->owned_nodes();
  ctx.active_nodes = halo_->reached_nodes();
}

#define MPM_SIMULATION_DISTRIBUTED(D)                                              \
  template void set_scatter_keys<D>(ParticleSet<D>&, const GridGeometry<D>&, int); \
  template void Simulation<D>::distribute(std::shared_ptr<Communicator>);          \
  template std::string Simulation<D>::why_not_distributed(int) const;              \
  template std::vector<int> Simulation<D>::balanced_slabs() const;                 \
  template void Simulation<D>::reassign_slabs(std::vector<int>);                   \
  template bool Simulation<D>::migrate();                                          \
  template std::vector<double> Simulation<D>::slab_costs() const;                  \
  template void Simulation<D>::rebalance();                                        \
  template void Simulation<D>::use_slabs(const std::vector<int>&);                 \
  template void Simulation<D>::share_report(StabilityReport&) const;               \
  template void Simulation<D>::attach(StepContext<D>&) const;
MPM_SIMULATION_DISTRIBUTED(1)
MPM_SIMULATION_DISTRIBUTED(2)
MPM_SIMULATION_DISTRIBUTED(3)
#undef MPM_SIMULATION_DISTRIBUTED

}  // namespace mpm
