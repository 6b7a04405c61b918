#include "mpm/slab_halo.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace mpm {

bool slab_baseline_requested() {
  static const bool requested = std::getenv("MPM_DEBUG_SLAB_BASELINE") != nullptr;
  return requested;
}

namespace {
// MPM_DEBUG_SLAB_BASELINE (hidden, for measuring the overlap: docs/distributed.md §5.2): the exchange as it was
// before the overlap, blocking after each colour round (no boundary slab first; each round's messages sent and
// received before the next round). The same messages and the same bits.
bool blocking() { return slab_baseline_requested(); }
}  // namespace

std::vector<int> cut_slabs(const std::vector<double>& cost, int ranks) {
  const int slabs = static_cast<int>(cost.size());
  if (ranks < 1 || ranks > slabs) throw std::invalid_argument("cut_slabs: between 1 and one rank per slab");
  std::vector<double> prefix(slabs + 1, 0);
  for (int s = 0; s < slabs; ++s) prefix[s + 1] = prefix[s] + cost[s];
  std::vector<int> first(ranks + 1, 0);
  first[ranks] = slabs;
  for (int r = 1; r < ranks; ++r) {
    const double target = prefix[slabs] * r / ranks;
    const int s = static_cast<int>(std::lower_bound(prefix.begin(), prefix.end(), target) - prefix.begin());
    first[r] = std::clamp(s, first[r - 1] + 1, slabs - (ranks - r));
  }
  return first;
}

SlabHalo::SlabHalo(Communicator& comm, std::vector<int> first_slab, int slab_cells, int reach_below, int reach_above,
                   int node_layers, Index nodes_per_layer)
    : comm_(&comm),
      first_slab_(std::move(first_slab)),
      slab_cells_(slab_cells),
      node_layers_(node_layers),
      nodes_per_layer_(nodes_per_layer) {
  const int n = comm.size(), me = comm.rank();
  if (static_cast<int>(first_slab_.size()) != n + 1) throw std::invalid_argument("SlabHalo: one slab range per rank");
  for (int r = 0; r < n; ++r)
    if (first_slab_[r + 1] <= first_slab_[r])
      throw std::invalid_argument("SlabHalo: rank " + std::to_string(r) + " owns no slab");
  // The boundary between ranks r and r + 1 is the face of slab S = first_slab[r + 1]; the overlap of the reach of
  // the slabs S - 1 and S is the node layers [ST - B, ST - 1 + A].
  for (int r = 0; r + 1 < n; ++r) {
    if (me != r && me != r + 1) continue;
    const int S = first_slab_[r + 1];
    const Index lo = std::max(0, S * slab_cells - reach_below);
    const Index hi = std::min(node_layers - 1, S * slab_cells - 1 + reach_above);
    if (lo > hi) continue;
    Overlap o;
    o.peer = me == r ? r + 1 : r;
    const int lower_colour = (S - 1) % 2;  // the colour of slab S - 1, rank r's; slab S has the other
    o.colour = me == r ? lower_colour : 1 - lower_colour;
    o.first = lo * nodes_per_layer;
    o.end = (hi + 1) * nodes_per_layer;
    o.slab = me == r ? S - 1 : S;
    overlaps_.push_back(o);
    auto& boundary = boundary_slabs_[o.colour];
    if (!blocking() && std::find(boundary.begin(), boundary.end(), o.slab) == boundary.end())
      boundary.push_back(o.slab);
  }
  send_.resize(overlaps_.size());
  receive_.resize(overlaps_.size());
  sending_.resize(overlaps_.size());
  receiving_.resize(overlaps_.size());
  const Index first_layer = std::max(0, first_slab_[me] * slab_cells - reach_below);
  const Index end_layer = std::min(node_layers, first_slab_[me + 1] * slab_cells + reach_above);
  reached_ = {first_layer * nodes_per_layer, end_layer * nodes_per_layer};
}

int SlabHalo::owner_of_slab(int slab) const {
  const auto it = std::upper_bound(first_slab_.begin(), first_slab_.end(), slab);
  return static_cast<int>(it - first_slab_.begin()) - 1;
}

std::pair<Index, Index> SlabHalo::owned_nodes() const {
  const int me = rank();
  const Index first = static_cast<Index>(first_slab_[me]) * slab_cells_;
  const Index last_layer =
      me + 1 == ranks() ? node_layers_ : std::min<Index>(node_layers_, first_slab_[me + 1] * Index{slab_cells_});
  return {first * nodes_per_layer_, last_layer * nodes_per_layer_};
}

void SlabHalo::pack(std::size_t k) const {
  const Overlap& o = overlaps_[k];
  const auto nodes = static_cast<std::size_t>(o.end - o.first);
  std::size_t per_node = 0;
  for (const HaloArray& a : arrays_) per_node += a.bytes_per_node;
  auto& buffer = send_[k];
  buffer.resize(nodes * per_node);
  std::byte* at = buffer.data();
  for (const HaloArray& a : arrays_) {
    const std::size_t bytes = nodes * a.bytes_per_node;
    std::memcpy(at, a.base + static_cast<std::size_t>(o.first) * a.bytes_per_node, bytes);
    at += bytes;
  }
  bytes_sent_ += buffer.size();
}

void SlabHalo::unpack(std::size_t k) const {
  const Overlap& o = overlaps_[k];
  const auto nodes = static_cast<std::size_t>(o.end - o.first);
  const std::byte* at = receive_[k].data();
  for (const HaloArray& a : arrays_) {
    const std::size_t bytes = nodes * a.bytes_per_node;
    std::memcpy(a.base + static_cast<std::size_t>(o.first) * a.bytes_per_node, at, bytes);
    at += bytes;
  }
}

void SlabHalo::begin_scatter(std::span<const HaloArray> arrays) const {
  const auto start = std::chrono::steady_clock::now();
  arrays_.assign(arrays.begin(), arrays.end());
  std::size_t per_node = 0;
  for (const HaloArray& a : arrays_) per_node += a.bytes_per_node;
  for (std::size_t k = 0; k < overlaps_.size(); ++k) {
    const Overlap& o = overlaps_[k];
    receive_[k].resize(static_cast<std::size_t>(o.end - o.first) * per_node);
    receiving_[k] = comm_->start_receive({o.peer, receive_[k]});
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void SlabHalo::before_round(int colour) const {
  if (colour == 0) return;  // the slabs of colour 0 scatter first at their overlaps: nothing to wait for
  const auto start = std::chrono::steady_clock::now();
  if (blocking()) {  // the exchange after round 0, as before the overlap: send and wait for the sends too
    for (std::size_t k = 0; k < overlaps_.size(); ++k)
      if (overlaps_[k].colour == 0) {
        pack(k);
        sending_[k] = comm_->start_send({overlaps_[k].peer, send_[k]});
      }
  }
  for (std::size_t k = 0; k < overlaps_.size(); ++k) {
    if (overlaps_[k].colour != colour || !receiving_[k]) continue;
    receiving_[k]->wait();
    receiving_[k].reset();
    unpack(k);
  }
  if (blocking())
    for (auto& t : sending_)
      if (t) {
        t->wait();
        t.reset();
      }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void SlabHalo::send(int colour) const {
  if (blocking()) return;  // sent after the whole round (before_round(1), end_scatter)
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < overlaps_.size(); ++k) {
    if (overlaps_[k].colour != colour) continue;
    pack(k);
    sending_[k] = comm_->start_send({overlaps_[k].peer, send_[k]});
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void SlabHalo::end_scatter() const {
  const auto start = std::chrono::steady_clock::now();
  if (blocking())  // the exchange after round 1
    for (std::size_t k = 0; k < overlaps_.size(); ++k)
      if (overlaps_[k].colour == 1) {
        pack(k);
        sending_[k] = comm_->start_send({overlaps_[k].peer, send_[k]});
      }
  for (std::size_t k = 0; k < overlaps_.size(); ++k) {
    if (receiving_[k]) {  // the totals of an overlap whose slab of this rank scattered first
      receiving_[k]->wait();
      receiving_[k].reset();
      unpack(k);
    }
    if (sending_[k]) {
      sending_[k]->wait();
      sending_[k].reset();
    }
  }
  arrays_.clear();
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace mpm
