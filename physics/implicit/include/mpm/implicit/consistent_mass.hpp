#pragma once
/// \file consistent_mass.hpp
/// The consistent mass matrix (86) M^AB = sum_pt m N^A(x_pt) N^B(x_pt) of linear hats, stored per node as its
/// 3^Dim neighbours (a node couples only with the nodes of the cells it touches), and the projection (87)
/// M v = sum_pt N pi by conjugate gradients with the lumped mass diag(sum_B M^AB) as preconditioner, per
/// velocity component on that component's free nodes (walls removed from the system, not zeroed after it).
/// M may be singular where cells are sparsely filled; the right side of (87) lies in its range, so CG still
/// converges there. Every sum runs in a fixed order: the same bits for any thread count.

#include <array>
#include <cmath>
#include <vector>

#include "mpm/grid.hpp"

namespace mpm::implicit {

inline constexpr int ipow3(int d) { return d == 0 ? 1 : 3 * ipow3(d - 1); }

template <int Dim>
class ConsistentMass {
 public:
  static constexpr int neighbours = ipow3(Dim);  ///< 3^Dim: offsets -1, 0, 1 per axis

  explicit ConsistentMass(const GridGeometry<Dim>& g) : g_(g), m_(g.node_count()), offset_{} {
    for (int o = 0; o < neighbours; ++o) {
      Index off = 0;
      for (int d = 0, r = o; d < Dim; ++d, r /= 3) off += (r % 3 - 1) * g.stride[d];
      offset_[o] = off;
    }
  }

  void clear() {
    for (auto& row : m_) row.fill(0);
  }
  /// Adds m N^A N^B for the nodes `node` (count) of one particle with weights `w` (eq. 86).
  template <std::size_t Count>
  void add_particle(Real mass, const std::array<Index, Count>& node, const std::array<Real, Count>& w) {
    for (std::size_t a = 0; a < Count; ++a)
      for (std::size_t b = 0; b < Count; ++b) m_[node[a]][slot(node[a], node[b])] += mass * w[a] * w[b];
  }
  /// The slot of node b in the row of node a (b within one cell of a on every axis).
  int slot(Index a, Index b) const {
    const auto ia = g_.node_indices(a), ib = g_.node_indices(b);
    int o = 0;
    for (int d = Dim - 1; d >= 0; --d) o = 3 * o + (ib[d] - ia[d] + 1);
    return o;
  }
  /// Linear index of the neighbour in slot o of node a (valid only where the entry is non-zero).
  Index neighbour(Index a, int o) const { return a + offset_[o]; }
  Real entry(Index a, int o) const { return m_[a][o]; }
  /// Row sum, the lumped mass of node a.
  Real lumped(Index a) const {
    Real s = 0;
    for (Real v : m_[a]) s += v;
    return s;
  }
  /// y_A = sum_B M^AB x_B for the nodes in `rows` (x, y indexed by grid node; entries outside `rows` of y untouched).
  template <class X, class Y>
  void multiply(const std::vector<Index>& rows, const X& x, Y& y) const {
    for (Index a : rows) {
      typename X::value_type sum = x[a] * Real(0);
      for (int o = 0; o < neighbours; ++o)
        if (m_[a][o] != 0) sum += m_[a][o] * x[a + offset_[o]];
      y[a] = sum;
    }
  }

 private:
  const GridGeometry<Dim>& g_;
  std::vector<std::array<Real, neighbours>> m_;
  std::array<Index, neighbours> offset_;
};

/// Solves M v = b for one velocity component on the nodes `free` (every other node of v is held at 0), by
/// preconditioned conjugate gradients (lumped mass), to ||b - M v|| <= rtol ||b||. v holds the start on entry.
/// Returns the iterations taken, or -1 when the tolerance was not reached in `max_iterations`.
template <int Dim>
int project_component(const ConsistentMass<Dim>& M, const std::vector<Index>& free, const std::vector<Real>& b,
                      std::vector<Real>& v, Real rtol, int max_iterations) {
  const std::size_t n = b.size();
  std::vector<Real> r(n, 0), z(n, 0), p(n, 0), q(n, 0), x(n, 0);
  for (Index a : free) x[a] = v[a];
  M.multiply(free, x, q);
  Real b2 = 0, rz = 0;
  for (Index a : free) {
    r[a] = b[a] - q[a];
    z[a] = r[a] / M.lumped(a);
    p[a] = z[a];
    b2 += b[a] * b[a];
    rz += r[a] * z[a];
  }
  const Real target = rtol * rtol * b2;
  for (int it = 0; it <= max_iterations; ++it) {
    Real r2 = 0;
    for (Index a : free) r2 += r[a] * r[a];
    if (r2 <= target) {
      for (Index a : free) v[a] = x[a];
      return it;
    }
    if (it == max_iterations) break;
    M.multiply(free, p, q);
    Real pq = 0;
    for (Index a : free) pq += p[a] * q[a];
    if (!(pq > 0)) break;
    const Real alpha = rz / pq;
    Real rz_new = 0;
    for (Index a : free) {
      x[a] += alpha * p[a];
      r[a] -= alpha * q[a];
      z[a] = r[a] / M.lumped(a);
      rz_new += r[a] * z[a];
    }
    const Real beta = rz_new / rz;
    rz = rz_new;
    for (Index a : free) p[a] = z[a] + beta * p[a];
  }
  for (Index a : free) v[a] = x[a];
  return -1;
}

}  // namespace mpm::implicit
