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

#include "mpm/grid/grid.hpp"
#include "mpm/implicit/free_dofs.hpp"

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

/// Solves (87) for one velocity component d in the Galerkin form P^T M P v = P^T b (free_dofs.hpp: v at the
/// masters `free` of d, at its slaves extrapolated; every other node of v is held at 0), by preconditioned conjugate
/// gradients (the lumped mass of P^T M P's rows, diag P^T M_L P), to ||P^T (b - M P v)|| <= rtol ||P^T b||. v holds
/// the start at the masters on entry and the solution at masters and slaves on return. Returns the iterations
/// taken, or -1 when the tolerance was not reached in `max_iterations`.
template <int Dim>
int project_component(const ConsistentMass<Dim>& M, const FreeDofs<Dim>& dofs, int d, const std::vector<Real>& b,
                      std::vector<Real>& v, Real rtol, int max_iterations) {
  const std::vector<Index>& free = dofs.free_nodes[d];
  const std::size_t n = b.size();
  std::vector<Index> rows = free;  // the rows M is applied on: masters and slaves
  for (const auto& s : dofs.slaves[d]) rows.push_back(s.node);
  std::vector<Real> r(n, 0), z(n, 0), p(n, 0), q(n, 0), x(n, 0), diag(n, 0), rhs(b);
  for (Index a : rows) diag[a] = M.lumped(a);
  for (const auto& s : dofs.slaves[d])
    for (const auto& [node, c] : s.terms) diag[node] += c * c * diag[s.node];
  dofs.restrict_to_masters(d, rhs);
  const auto apply = [&](std::vector<Real>& u, std::vector<Real>& out) {  // out = P^T M P u at the masters
    dofs.prolong(d, u);
    M.multiply(rows, u, out);
    dofs.restrict_to_masters(d, out);
  };
  for (Index a : free) x[a] = v[a];
  apply(x, q);
  Real b2 = 0, rz = 0;
  for (Index a : free) {
    r[a] = rhs[a] - q[a];
    z[a] = r[a] / diag[a];
    p[a] = z[a];
    b2 += rhs[a] * rhs[a];
    rz += r[a] * z[a];
  }
  const Real target = rtol * rtol * b2;
  const auto finish = [&](int result) {
    dofs.prolong(d, x);
    for (Index a : rows) v[a] = x[a];
    return result;
  };
  for (int it = 0; it <= max_iterations; ++it) {
    Real r2 = 0;
    for (Index a : free) r2 += r[a] * r[a];
    if (r2 <= target) return finish(it);
    if (it == max_iterations) break;
    apply(p, q);
    Real pq = 0;
    for (Index a : free) pq += p[a] * q[a];
    if (!(pq > 0)) break;
    const Real alpha = rz / pq;
    Real rz_new = 0;
    for (Index a : free) {
      x[a] += alpha * p[a];
      r[a] -= alpha * q[a];
      z[a] = r[a] / diag[a];
      rz_new += r[a] * z[a];
    }
    const Real beta = rz_new / rz;
    rz = rz_new;
    for (Index a : free) p[a] = z[a] + beta * p[a];
  }
  return finish(-1);
}

}  // namespace mpm::implicit
