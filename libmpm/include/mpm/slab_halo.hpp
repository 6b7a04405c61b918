#pragma once
/// \file slab_halo.hpp
/// The ghost-node protocol of a distributed run (issue 18, docs/distributed.md §4). Ranks own contiguous runs of
/// the slabs the threaded scatter already uses (tile_binning.hpp): slab s holds the cells [sT, (s+1)T) of the last
/// axis and its particles reach the node layers [sT - B, (s+1)T - 1 + A] (the shape function's slab_reach_below and
/// slab_reach_above, B + A <= T). A scatter runs even slabs, then odd ones; a node's contributions therefore come
/// from at most two slabs, in the order (even slab, odd slab), and inside a slab in the storage order, on one rank
/// as on many.
///
/// **Copy, never add.** Where the slabs S - 1 and S belong to two ranks, both hold the node layers
/// [ST - B, ST - 1 + A] (the overlap of the two slabs' reach; no other slab of either colour reaches them).
/// After the round of the colour of one of the two slabs, its owner sends the overlap layers to the other rank,
/// which replaces its copy by them; the other slab then adds its contributions in the next round, and its owner
/// sends the totals back. So both sides hold, bit for bit, the serial sums, with the serial order of terms; the
/// grid update, boundary conditions and the transfer back need no further message. Because the last axis varies
/// slowest in the node numbering (grid.hpp), the overlap is one contiguous range of nodes per array.

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>
#include <vector>

#include "mpm/communicator.hpp"
#include "mpm/types.hpp"

namespace mpm {

/// A nodal array a scatter writes: `bytes_per_node` bytes per node, node n at base + n * bytes_per_node.
struct HaloArray {
  std::byte* base = nullptr;
  std::size_t bytes_per_node = 0;
  template <class T>
  static HaloArray of(std::vector<T>& nodes) {
    return {reinterpret_cast<std::byte*>(nodes.data()), sizeof(T)};
  }
};

/// Contiguous runs of slabs, one per rank and at least one slab each, cut where the prefix of the slabs' `cost`
/// crosses r/ranks of the total: `first_slab` of SlabHalo (ranks <= cost.size()).
std::vector<int> cut_slabs(const std::vector<double>& cost, int ranks);

/// The cost of a slab: its particles, plus its nodes at a tenth of a particle (the grid update and reset).
inline double slab_cost(std::int64_t particles, Index nodes_per_layer, int slab_cells) {
  return static_cast<double>(particles) + 0.1 * static_cast<double>(nodes_per_layer) * slab_cells;
}

/// Which rank owns which slabs, and the exchange after a colour round. Built by the distributed simulation
/// (Simulation::distribute); a serial run has none (TileBins::halo is null).
class SlabHalo {
 public:
  /// `first_slab[r]` .. `first_slab[r + 1]` - 1: the slabs of rank r (every rank at least one).
  SlabHalo(Communicator& comm, std::vector<int> first_slab, int slab_cells, int reach_below, int reach_above,
           int node_layers, Index nodes_per_layer);

  Communicator& communicator() const { return *comm_; }
  int rank() const { return comm_->rank(); }
  int ranks() const { return comm_->size(); }
  int slab_count() const { return first_slab_.back(); }
  const std::vector<int>& first_slab() const { return first_slab_; }
  /// The rank owning slab s.
  int owner_of_slab(int slab) const;
  /// The node layers this rank owns ([first, last)): a node layer belongs to the slab whose cells start at or below
  /// it (the grid's last layer to the last slab). Sums over nodes (boundary work, reactions) take owned nodes only.
  std::pair<Index, Index> owned_nodes() const;
  /// The exchange of one scatter of `arrays` (for_each_tile_coloured). Its messages are those of the protocol above
  /// (after the round of its colour, the owner of an overlap's slab sends it; the other rank replaces its copy), each
  /// started as early as the data allows, so that the ranks compute while they travel:
  ///   begin_scatter(arrays)   starts every receive of the scatter;
  ///   before_round(colour)    waits for the partial sums the boundary slabs of this colour add to (the rank that
  ///                           scatters second at an overlap) and copies them in;
  ///   (the boundary slabs of the colour scatter)
  ///   send(colour)            starts sending the overlaps written by this colour's boundary slabs;
  ///   (the other slabs of the colour scatter: they write no overlap node)
  ///   end_scatter()           waits for the totals (the rank that scattered first) and for the sends.
  /// Slabs of one colour write disjoint nodes, so scattering the boundary slabs first changes no bit.
  void begin_scatter(std::span<const HaloArray> arrays) const;
  void before_round(int colour) const;
  void send(int colour) const;
  void end_scatter() const;
  /// This rank's slabs of `colour` that write an overlap (at most two): scattered first in their round.
  const std::vector<int>& boundary_slabs(int colour) const { return boundary_slabs_[colour]; }
  /// The nodes this rank's particles can reach, [first, end): its slabs' reach. The grid kernels reset and update
  /// only these (a rank's grid outside them is never read).
  std::pair<Index, Index> reached_nodes() const { return reached_; }
  /// Bytes this rank sent in exchanges so far (the halo model's count, docs/distributed.md).
  std::size_t bytes_sent() const { return bytes_sent_; }
  /// The halo model: bytes this rank sends per scatter of arrays of `bytes_per_node` (one message per rank boundary,
  /// its overlap's nodes; docs/distributed.md §5.2). A step sends it once per body and scatter (USL 1, MUSL and USF 2).
  std::size_t model_bytes_per_scatter(std::size_t bytes_per_node) const {
    std::size_t b = 0;
    for (const Overlap& o : overlaps_) b += static_cast<std::size_t>(o.end - o.first) * bytes_per_node;
    return b;
  }
  /// Wall seconds spent in exchanges so far (waiting for the other ranks included).
  double seconds() const { return seconds_; }

 private:
  struct Overlap {
    int peer;         ///< the other rank
    int colour;       ///< colour of the round after which this rank sends (the other colour: receives)
    Index first = 0;  ///< nodes [first, end)
    Index end = 0;
    int slab = 0;  ///< this rank's slab that writes the overlap (its colour is `colour`)
  };
  void pack(std::size_t k) const;
  void unpack(std::size_t k) const;
  Communicator* comm_;
  std::vector<int> first_slab_;
  int slab_cells_;
  int node_layers_;
  Index nodes_per_layer_;
  std::vector<Overlap> overlaps_;  ///< this rank's (at most two)
  mutable std::vector<std::vector<std::byte>> send_, receive_;
  std::vector<int> boundary_slabs_[2];
  // The scatter in progress (begin_scatter .. end_scatter): its arrays and the messages in flight, per overlap.
  mutable std::vector<HaloArray> arrays_;
  mutable std::vector<std::unique_ptr<Communicator::Transfer>> sending_, receiving_;
  std::pair<Index, Index> reached_;
  mutable std::size_t bytes_sent_ = 0;
  mutable double seconds_ = 0;
};

}  // namespace mpm
