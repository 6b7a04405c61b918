#include "mpm/parallel/tile_halo.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

#include "mpm/grid/tile_binning.hpp"

namespace mpm {

namespace {

struct TileBox {
  std::array<int, 3> lo{0, 0, 0}, hi{1, 1, 1};  // tile coordinates [lo, hi)
  Index count() const { return Index{hi[0] - lo[0]} * (hi[1] - lo[1]) * (hi[2] - lo[2]); }
};

void bisect(const TileGrid& grid, std::span<const double> cost, TileBox box, int first_rank, int ranks,
            std::vector<int>& owner) {
  if (ranks == 1) {
    for (int c2 = box.lo[2]; c2 < box.hi[2]; ++c2)
      for (int c1 = box.lo[1]; c1 < box.hi[1]; ++c1)
        for (int c0 = box.lo[0]; c0 < box.hi[0]; ++c0)
          owner[static_cast<std::size_t>(grid.index({c0, c1, c2}))] = first_rank;
    return;
  }
  // Along each axis that can be cut: the cost of every layer of tiles, and the cut s (layers [0, s) low) nearest
  // the low half's share of the ranks.
  const int low_ranks = ranks / 2;
  struct Cut {
    int axis = -1, s = 1;
    double error = 0;
    long extent = 0;
  };
  std::vector<Cut> cuts;
  double total = 0;
  for (int d = 0; d < grid.dim; ++d) {
    const int layers = box.hi[d] - box.lo[d];
    if (layers < 2) continue;
    std::vector<double> prefix(static_cast<std::size_t>(layers) + 1, 0.0);
    for (int c2 = box.lo[2]; c2 < box.hi[2]; ++c2)
      for (int c1 = box.lo[1]; c1 < box.hi[1]; ++c1)
        for (int c0 = box.lo[0]; c0 < box.hi[0]; ++c0) {
          const std::array<int, 3> c{c0, c1, c2};
          prefix[static_cast<std::size_t>(c[d] - box.lo[d]) + 1] += cost[static_cast<std::size_t>(grid.index(c))];
        }
    for (int l = 0; l < layers; ++l) prefix[l + 1] += prefix[l];
    total = prefix[layers];
    const double target = total * low_ranks / ranks;
    Cut cut;
    cut.axis = d;
    for (int l = 2; l < layers; ++l)
      if (std::abs(prefix[l] - target) < std::abs(prefix[cut.s] - target)) cut.s = l;
    cut.error = std::abs(prefix[cut.s] - target);
    cut.extent = std::min(grid.cells[d], box.hi[d] * grid.tile_cells[d]) - box.lo[d] * grid.tile_cells[d];
    cuts.push_back(cut);
  }
  // The longest axis in cells among those whose cut misses the share by at most 1% of the box's cost more than
  // the best one (compact boxes, few ghost nodes, unless another axis balances clearly better); on a tie the later
  // axis (the last axis first: slabs, whose overlaps are contiguous runs of nodes).
  double best = cuts.front().error;
  for (const Cut& c : cuts) best = std::min(best, c.error);
  Cut chosen;
  chosen.extent = -1;
  for (const Cut& c : cuts)
    if (c.error <= best + 0.01 * total && c.extent >= chosen.extent) chosen = c;
  const int axis = chosen.axis, s = chosen.s;
  const int layers = box.hi[axis] - box.lo[axis];
  const Index slice = box.count() / layers;  // tiles per layer
  // The ranks on each side: the halves, or as near as one rank per tile allows.
  const int low = static_cast<int>(std::clamp<Index>(low_ranks, std::max<Index>(1, ranks - (layers - s) * slice),
                                                     std::min<Index>(ranks - 1, s * slice)));
  TileBox lower = box, upper = box;
  lower.hi[axis] = box.lo[axis] + s;
  upper.lo[axis] = box.lo[axis] + s;
  bisect(grid, cost, lower, first_rank, low, owner);
  bisect(grid, cost, upper, first_rank + low, ranks - low, owner);
}

}  // namespace

std::vector<int> bisect_tiles(const TileGrid& grid, std::span<const double> cost, int ranks) {
  if (ranks < 1 || ranks > grid.tile_count())
    throw std::invalid_argument("bisect_tiles: between 1 rank and one rank per tile");
  if (static_cast<Index>(cost.size()) != grid.tile_count())
    throw std::invalid_argument("bisect_tiles: one cost per tile");
  std::vector<int> owner(static_cast<std::size_t>(grid.tile_count()), 0);
  TileBox all;
  all.hi = grid.tiles;
  bisect(grid, cost, all, 0, ranks, owner);
  return owner;
}

namespace {

/// Whether the node reaches of tiles a and b (coordinates on axis d) overlap.
bool reaches_overlap(const TileGrid& grid, int d, int a, int b) {
  const auto [a0, a1] = grid.reach(d, a);
  const auto [b0, b1] = grid.reach(d, b);
  return a0 <= b1 && b0 <= a1;
}

}  // namespace

std::vector<std::uint8_t> shared_writing_tiles(const TileGrid& grid, std::span<const int> owner) {
  // Tiles are at least a reach wide, so only neighbours overlap; two tiles on each side are checked all the same.
  std::vector<std::uint8_t> shared(static_cast<std::size_t>(grid.tile_count()), 0);
  for (Index t = 0; t < grid.tile_count(); ++t) {
    const auto c = grid.coordinates(t);
    std::array<int, 3> lo{0, 0, 0}, hi{0, 0, 0}, n{};
    for (int d = 0; d < grid.dim; ++d) {
      lo[d] = std::max(0, c[d] - 2);
      hi[d] = std::min(grid.tiles[d] - 1, c[d] + 2);
    }
    bool found = false;
    for (n[2] = lo[2]; n[2] <= hi[2] && !found; ++n[2])
      for (n[1] = lo[1]; n[1] <= hi[1] && !found; ++n[1])
        for (n[0] = lo[0]; n[0] <= hi[0] && !found; ++n[0]) {
          if (owner[static_cast<std::size_t>(grid.index(n))] == owner[static_cast<std::size_t>(t)]) continue;
          bool all = true;
          for (int d = 0; d < grid.dim; ++d) all = all && reaches_overlap(grid, d, c[d], n[d]);
          found = all;
        }
    shared[static_cast<std::size_t>(t)] = found ? 1 : 0;
  }
  return shared;
}

HaloPlan plan_halo(const TileGrid& grid, std::span<const int> owner, int rank) {
  if (static_cast<Index>(owner.size()) != grid.tile_count())
    throw std::invalid_argument("plan_halo: one owner per tile");
  HaloPlan plan;
  // This rank's tiles, the box of tile coordinates around them, and the box of nodes they reach.
  std::array<int, 3> tile_lo{grid.tiles}, tile_hi{0, 0, 0};
  std::array<int, 3> node_lo{grid.nodes}, node_hi{0, 0, 0};  // [lo, hi]
  Index mine = 0;
  for (Index t = 0; t < grid.tile_count(); ++t) {
    if (owner[static_cast<std::size_t>(t)] != rank) continue;
    ++mine;
    const auto c = grid.coordinates(t);
    for (int d = 0; d < 3; ++d) {
      tile_lo[d] = std::min(tile_lo[d], c[d]);
      tile_hi[d] = std::max(tile_hi[d], c[d] + 1);
      const auto [first, last] = d < grid.dim ? grid.reach(d, c[d]) : std::pair<int, int>{0, 0};
      node_lo[d] = std::min(node_lo[d], first);
      node_hi[d] = std::max(node_hi[d], last);
    }
  }
  if (mine == 0) throw std::invalid_argument("plan_halo: rank " + std::to_string(rank) + " owns no tile");
  plan.is_box = Index{tile_hi[0] - tile_lo[0]} * (tile_hi[1] - tile_lo[1]) * (tile_hi[2] - tile_lo[2]) == mine;
  for (int d = 0; d < 3; ++d)
    plan.cell_box[d] = {tile_lo[d] * grid.tile_cells[d], std::min(grid.cells[d], tile_hi[d] * grid.tile_cells[d])};
  if (plan.is_box) {
    // A tile of the box writes shared nodes iff on some axis a tile outside the box, within two tiles along that axis
    // only, has an overlapping reach (the test of TileHalo's constructor: a tile differing on other axes too lies
    // outside on one axis, and the tile across on that axis alone overlaps as well).
    for (int d = 0; d < grid.dim; ++d) {
      auto& flags = plan.cell_flags[static_cast<std::size_t>(d)];
      flags.assign(static_cast<std::size_t>(grid.cells[d]), 0);
      for (int c = 0; c < grid.cells[d]; ++c) {
        const int tc = c / grid.tile_cells[d];
        if (tc < tile_lo[d] || tc >= tile_hi[d]) {
          flags[static_cast<std::size_t>(c)] = 1;
          continue;
        }
        for (int n = std::max(0, tc - 2); n <= std::min(grid.tiles[d] - 1, tc + 2); ++n)
          if ((n < tile_lo[d] || n >= tile_hi[d]) && reaches_overlap(grid, d, tc, n))
            flags[static_cast<std::size_t>(c)] = 2;
      }
    }
  }
  const auto node_index = [&](const std::array<int, 3>& k) {
    return k[0] + Index{grid.nodes[0]} * (k[1] + Index{grid.nodes[1]} * k[2]);
  };
  plan.owned.assign(static_cast<std::size_t>(grid.node_count()), 0);

  // Every node this rank holds, in ascending order: its writers in colour order, and who sends it after which.
  std::map<std::pair<int, int>, std::vector<Index>> sends, receives;  // (colour, peer) -> nodes
  std::vector<std::uint8_t> boundary(static_cast<std::size_t>(grid.tile_count()), 0);
  struct Writer {
    int colour;
    Index tile;
    int owner;
  };
  std::array<int, 3> k{};
  for (k[2] = node_lo[2]; k[2] <= node_hi[2]; ++k[2])
    for (k[1] = node_lo[1]; k[1] <= node_hi[1]; ++k[1])
      for (k[0] = node_lo[0]; k[0] <= node_hi[0]; ++k[0]) {
        // Writers per axis: the tiles t with t w - B <= k <= (t + 1) w - 1 + A.
        std::array<int, 3> first{0, 0, 0}, last{0, 0, 0};
        for (int d = 0; d < grid.dim; ++d) std::tie(first[d], last[d]) = grid.writers(d, k[d]);
        std::array<Writer, 8> writers{};
        int count = 0;
        bool held = false;
        for (int t2 = first[2]; t2 <= last[2]; ++t2)
          for (int t1 = first[1]; t1 <= last[1]; ++t1)
            for (int t0 = first[0]; t0 <= last[0]; ++t0) {
              const Index t = grid.index({t0, t1, t2});
              const int o = owner[static_cast<std::size_t>(t)];
              writers[count++] = {grid.colour(t), t, o};
              held = held || o == rank;
            }
        if (!held) continue;
        const Index n = node_index(k);
        if (!plan.held.empty() && plan.held.back().second == n)
          ++plan.held.back().second;
        else
          plan.held.emplace_back(n, n + 1);
        std::array<int, 3> own_tile{};
        for (int d = 0; d < 3; ++d) own_tile[d] = d < grid.dim ? grid.tile_of_node(d, k[d]) : 0;
        if (owner[static_cast<std::size_t>(grid.index(own_tile))] == rank) plan.owned[static_cast<std::size_t>(n)] = 1;
        std::sort(writers.begin(), writers.begin() + count,
                  [](const Writer& a, const Writer& b) { return a.colour < b.colour; });
        for (int j = 0; j < count; ++j) {
          const int from = writers[j].owner;
          const bool final_sum = j + 1 == count;
          if (!final_sum && writers[j + 1].owner == from) continue;  // the next writer adds on the same rank
          // Recipients: the next writer's owner, or after the last writer every other holder.
          std::array<int, 8> to{};
          int recipients = 0;
          for (int i = final_sum ? 0 : j + 1; i < (final_sum ? count : j + 2); ++i) {
            const int r = writers[i].owner;
            if (r != from && std::find(to.begin(), to.begin() + recipients, r) == to.begin() + recipients)
              to[recipients++] = r;
          }
          if (from == rank) {
            for (int i = 0; i < recipients; ++i) sends[{writers[j].colour, to[i]}].push_back(n);
            if (recipients > 0) boundary[static_cast<std::size_t>(writers[j].tile)] = 1;
          } else if (std::find(to.begin(), to.begin() + recipients, rank) != to.begin() + recipients) {
            receives[{writers[j].colour, from}].push_back(n);
          }
        }
      }
  const auto messages = [](const std::map<std::pair<int, int>, std::vector<Index>>& lists) {
    std::vector<HaloMessage> out;
    for (const auto& [key, nodes] : lists) {
      HaloMessage m;
      m.colour = key.first;
      m.peer = key.second;
      m.nodes = static_cast<Index>(nodes.size());
      for (const Index n : nodes)
        if (!m.runs.empty() && m.runs.back().second == n)
          ++m.runs.back().second;
        else
          m.runs.emplace_back(n, n + 1);
      out.push_back(std::move(m));
    }
    return out;
  };
  plan.sends = messages(sends);
  plan.receives = messages(receives);
  for (Index t = 0; t < grid.tile_count(); ++t)
    if (owner[static_cast<std::size_t>(t)] == rank)
      (boundary[static_cast<std::size_t>(t)] ? plan.boundary_tiles : plan.inner_tiles)[grid.colour(t)].push_back(t);
  return plan;
}

TileHalo::TileHalo(Communicator& comm, const TileGrid& grid, std::vector<int> owner)
    : comm_(&comm), grid_(grid), owner_(std::move(owner)) {
  for (const int o : owner_)
    if (o < 0 || o >= comm.size())
      throw std::invalid_argument("TileHalo: a tile's owner " + std::to_string(o) + " is not a rank");
  plan_ = plan_halo(grid_, owner_, comm.rank());
  writes_shared_ = shared_writing_tiles(grid_, owner_);
  own_shared_.assign(writes_shared_.size(), 0);
  for (std::size_t t = 0; t < own_shared_.size(); ++t)
    own_shared_[t] = writes_shared_[t] != 0 && owner_[t] == comm.rank() ? 1 : 0;
  Index stride = 1;
  for (int d = 0; d < grid_.dim; ++d) {
    tile_term_[d].resize(static_cast<std::size_t>(grid_.cells[d]));
    for (int k = 0; k < grid_.cells[d]; ++k)
      tile_term_[d][static_cast<std::size_t>(k)] = stride * std::min(k / grid_.tile_cells[d], grid_.tiles[d] - 1);
    stride *= grid_.tiles[d];
  }
  send_.resize(plan_.sends.size());
  receive_.resize(plan_.receives.size());
  sending_.resize(plan_.sends.size());
  receiving_.resize(plan_.receives.size());
}

void TileHalo::pack(std::size_t k) const {
  const HaloMessage& m = plan_.sends[k];
  std::size_t per_node = 0;
  for (const HaloArray& a : arrays_) per_node += a.bytes_per_node;
  auto& buffer = send_[k];
  buffer.resize(static_cast<std::size_t>(m.nodes) * per_node);
  std::byte* at = buffer.data();
  for (const HaloArray& a : arrays_)
    for (const auto& [first, end] : m.runs) {
      const std::size_t bytes = static_cast<std::size_t>(end - first) * a.bytes_per_node;
      std::memcpy(at, a.base + static_cast<std::size_t>(first) * a.bytes_per_node, bytes);
      at += bytes;
    }
  bytes_sent_ += buffer.size();
}

void TileHalo::begin_scatter(std::span<const HaloArray> arrays) const {
  const auto start = std::chrono::steady_clock::now();
  arrays_.assign(arrays.begin(), arrays.end());
  std::size_t per_node = 0;
  for (const HaloArray& a : arrays_) per_node += a.bytes_per_node;
  for (std::size_t k = 0; k < plan_.receives.size(); ++k) {
    const HaloMessage& m = plan_.receives[k];
    receive_[k].resize(static_cast<std::size_t>(m.nodes) * per_node);
    receiving_[k] = comm_->start_receive({m.peer, receive_[k]});
  }
  applied_ = 0;
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void TileHalo::apply_received(int below_colour) const {
  for (; applied_ < plan_.receives.size() && plan_.receives[applied_].colour < below_colour; ++applied_) {
    receiving_[applied_]->wait();
    receiving_[applied_].reset();
    const HaloMessage& m = plan_.receives[applied_];
    const std::byte* at = receive_[applied_].data();
    for (const HaloArray& a : arrays_)
      for (const auto& [first, end] : m.runs) {
        const std::size_t bytes = static_cast<std::size_t>(end - first) * a.bytes_per_node;
        std::memcpy(a.base + static_cast<std::size_t>(first) * a.bytes_per_node, at, bytes);
        at += bytes;
      }
  }
}

void TileHalo::before_round(int colour) const {
  const auto start = std::chrono::steady_clock::now();
  apply_received(colour);
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void TileHalo::send(int colour) const {
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < plan_.sends.size(); ++k) {
    if (plan_.sends[k].colour != colour) continue;
    pack(k);
    sending_[k] = comm_->start_send({plan_.sends[k].peer, send_[k]});
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void TileHalo::end_scatter() const {
  const auto start = std::chrono::steady_clock::now();
  apply_received(grid_.colours());
  for (auto& t : sending_)
    if (t) {
      t->wait();
      t.reset();
    }
  arrays_.clear();
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace mpm
