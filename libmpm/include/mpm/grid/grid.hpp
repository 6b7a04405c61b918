#pragma once
/// \file grid.hpp
/// Cartesian background grid: geometry (origin, cell size, node counts) and the nodal arrays that the
/// transfers fill every step (mass, momentum, force, velocities). Node (i, j, k) has linear index
/// i + n_x (j + n_y k): x varies fastest, so the last axis is the one cut into slabs for the parallel
/// particle-to-grid scatter (see tile_binning.hpp).

#include <array>
#include <map>
#include <string>
#include <vector>

#include "mpm/core/coordinates.hpp"
#include "mpm/core/types.hpp"
#include "mpm/grid/reserved_pages.hpp"

namespace mpm {

/// Unaligned fixed-size vector: node records are packed without padding.
template <int Dim>
using VecU = Eigen::Matrix<Real, Dim, 1, Eigen::DontAlign>;
template <int Dim>
using MatU = Eigen::Matrix<Real, Dim, Dim, Eigen::DontAlign>;

/// Geometry of the grid: everything the shape functions need, nothing else.
template <int Dim>
struct GridGeometry {
  Vec<Dim> origin = Vec<Dim>::Zero();  ///< m, position of node 0
  Vec<Dim> h = Vec<Dim>::Ones();       ///< m, cell size per axis
  Vec<Dim> inv_h = Vec<Dim>::Ones();   ///< 1/m
  std::array<int, Dim> nodes{};        ///< nodes per axis (cells + 1)
  std::array<Index, Dim> stride{};     ///< linear-index stride per axis
  /// Axisymmetric (2D only): x is the radius, origin[0] = 0 the axis (coordinates.hpp). The kernels take this
  /// choice at compile time (their Coords parameter); the field is for what is built once (face areas, output).
  Coordinates coordinates = Coordinates::cartesian;

  GridGeometry() = default;
  GridGeometry(const Vec<Dim>& origin_, const Vec<Dim>& h_, const std::array<int, Dim>& cells,
               Coordinates coordinates_ = Coordinates::cartesian)
      : origin(origin_), h(h_), inv_h(h_.cwiseInverse()), coordinates(coordinates_) {
    Index s = 1;
    for (int d = 0; d < Dim; ++d) {
      nodes[d] = cells[d] + 1;
      stride[d] = s;
      s *= nodes[d];
    }
  }
  Index node_count() const {
    Index n = 1;
    for (int d = 0; d < Dim; ++d) n *= nodes[d];
    return n;
  }
  int cells(int d) const { return nodes[d] - 1; }
  /// Upper corner of the box, m.
  Vec<Dim> upper() const {
    Vec<Dim> u;
    for (int d = 0; d < Dim; ++d) u[d] = origin[d] + h[d] * cells(d);
    return u;
  }
  /// Position of a node from its per-axis indices.
  Vec<Dim> node_position(const std::array<int, Dim>& ijk) const {
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = origin[d] + h[d] * ijk[d];
    return x;
  }
  /// Per-axis indices of a node from its linear index.
  std::array<int, Dim> node_indices(Index linear) const {
    std::array<int, Dim> ijk{};
    for (int d = 0; d < Dim; ++d) {
      ijk[d] = static_cast<int>(linear % nodes[d]);
      linear /= nodes[d];
    }
    return ijk;
  }
  /// Volume (length in 1D, area in 2D) of one cell.
  Real cell_volume() const { return h.prod(); }
};

/// What the particle-to-grid scatter accumulates per node, packed in one record so that a scatter
/// touches one cache line per node.
template <int Dim>
struct NodeRecord {
  Real mass;
  VecU<Dim> momentum;
  VecU<Dim> force;
};

/// The two nodal velocities a grid-to-particle transfer reads, side by side in memory.
/// `mapped`: obtained from mapped particle momentum, v_I^t after the first mapping (and, in MUSL, the
/// re-mapped v_I^{t+dt} of eq. 2.64-2.65 after the second). `updated`: after the momentum update
/// with the nodal forces, v_I^{t+dt} in USL and the trial velocity v~_I of MUSL (Alg. 1-2).
template <int Dim>
struct NodeVelocity {
  VecU<Dim> mapped;
  VecU<Dim> updated;
};

/// An array of node records whose pages get memory only where a kernel writes (reserved_pages.hpp): with sparse
/// tiles, the nodes no particle reaches cost no memory.
template <class T>
using NodeArray = std::vector<T, ReservedPages<T>>;

/// The background grid: geometry plus nodal fields, reset every step.
template <int Dim>
struct Grid {
  GridGeometry<Dim> geometry;
  NodeArray<NodeRecord<Dim>> node;        ///< mass (kg), momentum (kg m/s), force (N)
  NodeArray<NodeVelocity<Dim>> velocity;  ///< m/s
  /// Nodal scalar fields that optional modules keep (the thermal module's "temperature", K), by name; written
  /// with the grid output. Empty unless a module fills it.
  std::map<std::string, std::vector<Real>> node_fields;

  explicit Grid(const GridGeometry<Dim>& g = {}) : geometry(g), node(g.node_count()), velocity(g.node_count()) {}
  Index size() const { return static_cast<Index>(node.size()); }
  /// Gives the whole memory pages of nodes [first, end) of `node` and `velocity` back to the system (they read as
  /// zeros afterwards): for nodes whose content is zero or no longer read (ActiveTiles::left).
  void release_nodes(Index first, Index end) {
    release_pages(node.data() + first, sizeof(NodeRecord<Dim>) * static_cast<std::size_t>(end - first));
    release_pages(velocity.data() + first, sizeof(NodeVelocity<Dim>) * static_cast<std::size_t>(end - first));
  }
  /// Zeroes every node record and velocity, giving the whole pages back (a grid as new: ActiveTiles::zeroed).
  void clear() {
    zero_bytes(node.data(), sizeof(NodeRecord<Dim>) * node.size());
    zero_bytes(velocity.data(), sizeof(NodeVelocity<Dim>) * velocity.size());
  }
  /// Bytes of `node` and `velocity` in memory (reserved_pages.hpp: pages no kernel wrote cost none).
  std::size_t resident_bytes() const {
    return mpm::resident_bytes(node.data(), sizeof(NodeRecord<Dim>) * node.size()) +
           mpm::resident_bytes(velocity.data(), sizeof(NodeVelocity<Dim>) * velocity.size());
  }
};

}  // namespace mpm
