#pragma once
/// \file tile_halo.hpp
/// The ghost-node protocol of a distributed run (docs/distributed.md §5.2). Ranks own sets of the tiles
/// the threaded scatter already uses (tile_binning.hpp; blocks cut by recursive bisection, any set works). The tiles
/// of one colour (the parities of their coordinates, 2^d colours) write disjoint nodes, and a scatter runs the
/// colours in turn, so a node's contributions come from at most 2^d tiles, in colour order, and inside a tile in the
/// storage order, on one rank as on many.
///
/// **Copy, never add.** A node's *writers* are the tiles whose particles can reach it, in colour order; its *holders*
/// the ranks owning a writer. After the round of writer j, its owner sends the node to the owner of writer j + 1 when
/// that is another rank, which **replaces** its copy before its own round; after the last writer, its owner sends the
/// total to every other holder. So each holder ends with the serial sum and the serial order of terms, bit for bit,
/// and the grid update, boundary conditions and the transfer back need no further message. A message is one (colour,
/// peer) pair's nodes, in ascending node order on both sides; a rank applies what it received in colour order before
/// each round, so a later partial sum always replaces an earlier one.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "mpm/core/types.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/grid/node_runs.hpp"
#include "mpm/grid/scatter_exchange.hpp"
#include "mpm/grid/tile_grid.hpp"
#include "mpm/parallel/communicator.hpp"

namespace mpm {

/// The cost of a tile: its particles, plus its nodes at a tenth of a particle (the grid update and reset).
inline double tile_cost(std::int64_t particles, Index cells_in_tile) {
  return static_cast<double>(particles) + 0.1 * static_cast<double>(cells_in_tile);
}

/// Owner of each tile for `ranks` ranks, by recursive coordinate bisection of the tile box: cut the longest axis
/// (in cells; the last axis on a tie) where the cost prefix crosses the low half's share of the ranks, recursively.
/// Every rank owns a box of tiles, at least one (ranks <= tile_count()); deterministic, so the same on every rank.
std::vector<int> bisect_tiles(const TileGrid& grid, std::span<const double> cost, int ranks);

/// One message of a scatter's exchange: the nodes of one (colour, peer) pair, ascending, as runs [first, end).
struct HaloMessage {
  int colour = 0;
  int peer = 0;
  std::vector<std::pair<Index, Index>> runs;
  Index nodes = 0;
};

/// What one rank sends and receives in a scatter, and which of its tiles scatter first: a function of the tiles'
/// owners only (every rank computes its own; `mpm check --ranks N` computes every rank's).
struct HaloPlan {
  std::vector<HaloMessage> sends, receives;  ///< by colour, then peer
  /// Per colour: this rank's tiles that write a node it sends after that colour (scattered first, so that their
  /// messages leave while the others scatter), and its other tiles.
  std::array<std::vector<Index>, 8> boundary_tiles, inner_tiles;
  std::vector<NodeRun> held;        ///< the nodes this rank's tiles reach (its grid kernels visit these)
  std::vector<std::uint8_t> owned;  ///< per node of the grid: 1 where the node's tile is this rank's
  /// Whether this rank's tiles are exactly a box of tile coordinates; `cell_box` is then its cells, [lo, hi) per axis.
  bool is_box = false;
  std::array<std::pair<int, int>, 3> cell_box{};
  /// Box plans only, per axis and cell of the grid: bit 1 when the cell lies outside cell_box on that axis, bit 2 when
  /// it lies inside and its tile's reach overlaps the reach of a tile across a face of the box on that axis (which
  /// another rank owns). For the cells (c_0 .. c_d-1) of a particle: it is outside the box iff some flag has bit 1,
  /// and it is outside or in a tile that writes shared nodes (TileHalo::writes_shared) iff some flag is non-zero: the
  /// post-step pass over the particles (Simulation::scan_particles) needs a lookup per axis and nothing else (32-bit
  /// entries: the lookups vectorise as gathers, which bytes do not).
  std::array<std::vector<std::uint32_t>, 3> cell_flags;
  /// The halo model: bytes this rank sends per scatter of arrays of `bytes_per_node` in all.
  std::size_t bytes_per_scatter(std::size_t bytes_per_node) const {
    std::size_t n = 0;
    for (const HaloMessage& m : sends) n += static_cast<std::size_t>(m.nodes);
    return n * bytes_per_node;
  }
};

/// Per tile, 1 when its reach overlaps the reach of a tile of another owner on every axis: its particles can write a
/// node that more than one rank holds (TileHalo::writes_shared).
std::vector<std::uint8_t> shared_writing_tiles(const TileGrid& grid, std::span<const int> owner);

/// The plan of rank `rank` when tile t belongs to `owner[t]`; throws std::invalid_argument when that rank owns no tile.
HaloPlan plan_halo(const TileGrid& grid, std::span<const int> owner, int rank);

/// Which rank owns which tiles, and the exchange of a scatter. Built by the distributed simulation
/// (Simulation::distribute); a serial run has none (TileBins::halo is null).
class TileHalo final : public ScatterExchange {
 public:
  TileHalo(Communicator& comm, const TileGrid& grid, std::vector<int> owner);

  Communicator& communicator() const { return *comm_; }
  int rank() const { return comm_->rank(); }
  int ranks() const { return comm_->size(); }
  const TileGrid& tiles() const { return grid_; }
  /// Owner of every tile (the same vector on every rank).
  const std::vector<int>& owners() const { return owner_; }
  const HaloPlan& plan() const { return plan_; }
  /// Whether this rank owns node `n`: every node has one owner, the owner of the tile whose cells start at or below
  /// it on every axis. Sums over nodes (boundary work, reactions, the output's grid) take owned nodes only.
  bool owns_node(Index n) const { return plan_.owned[static_cast<std::size_t>(n)] != 0; }
  NodeMask owned_nodes() const { return {plan_.owned.data()}; }
  /// The nodes this rank's particles can reach: the grid kernels reset and update only these (a rank's grid outside
  /// them is never read).
  NodeRuns held_nodes() const { return NodeRuns::of(plan_.held); }
  Index tile_count() const override { return grid_.tile_count(); }
  const std::vector<Index>& boundary_tiles(int colour) const override { return plan_.boundary_tiles[colour]; }
  const std::vector<Index>& inner_tiles(int colour) const override { return plan_.inner_tiles[colour]; }
  /// Whether the particles of tile t can write a node that more than one rank holds: a tile whose reach overlaps
  /// the reach of a tile of another rank (the same answer on every rank). A body none of whose particles sits in
  /// such a tile changes no ghost node in a scatter, which then needs no exchange (TileBins::exchange).
  bool writes_shared(Index t) const { return writes_shared_[static_cast<std::size_t>(t)] != 0; }
  /// Per tile, 1 for this rank's tiles that write shared nodes: with sparse tiles the grid kernels always visit their
  /// reach, which holds every node an exchange writes on this rank and every node it owns that another rank's
  /// particles reach (ActiveTiles::always_mark).
  std::span<const std::uint8_t> own_shared_tiles() const { return own_shared_; }
  /// The tile-number term of cell c on axis d (coordinate x the axis's tile stride): a tile's number is the sum
  /// over the axes, a table lookup per axis instead of a division.
  Index tile_term(int d, int c) const { return tile_term_[d][static_cast<std::size_t>(c)]; }

  /// The exchange of one scatter of `arrays` (for_each_tile_coloured), each message started as early as its data
  /// exists and waited for only when its data is needed, so that the ranks compute while they travel:
  ///   begin_scatter(arrays)   posts every receive of the scatter;
  ///   before_round(colour)    applies, in colour order, what the earlier colours' owners sent;
  ///   (the boundary tiles of the colour scatter)
  ///   send(colour)            starts this colour's messages;
  ///   (the inner tiles of the colour scatter: they write no node sent after this colour)
  ///   end_scatter()           applies the rest (totals) and waits for the sends.
  void begin_scatter(std::span<const HaloArray> arrays) const override;
  void before_round(int colour) const override;
  void send(int colour) const override;
  void end_scatter() const override;

  /// Bytes this rank sent in exchanges so far (the halo model's count: plan().bytes_per_scatter per exchange).
  std::size_t bytes_sent() const { return bytes_sent_; }
  std::size_t model_bytes_per_scatter(std::size_t bytes_per_node) const {
    return plan_.bytes_per_scatter(bytes_per_node);
  }
  /// Wall seconds spent in exchanges so far (waiting for the other ranks included).
  double seconds() const { return seconds_; }

 private:
  void pack(std::size_t k) const;
  void apply_received(int below_colour) const;
  Communicator* comm_;
  TileGrid grid_;
  std::vector<int> owner_;
  HaloPlan plan_;
  std::vector<std::uint8_t> writes_shared_;      ///< per tile
  std::vector<std::uint8_t> own_shared_;         ///< per tile: this rank's and writes_shared
  std::array<std::vector<Index>, 3> tile_term_;  ///< per axis and cell
  mutable std::vector<std::vector<std::byte>> send_, receive_;
  // The scatter in progress (begin_scatter .. end_scatter): its arrays and the messages in flight.
  mutable std::vector<HaloArray> arrays_;
  mutable std::vector<std::unique_ptr<Communicator::Transfer>> sending_, receiving_;
  mutable std::size_t applied_ = 0;  ///< receives applied so far in this scatter (they are in colour order)
  mutable std::size_t bytes_sent_ = 0;
  mutable double seconds_ = 0;
};

}  // namespace mpm
