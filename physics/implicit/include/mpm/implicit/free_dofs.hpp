#pragma once
/// \file free_dofs.hpp
/// The unknowns of one implicit step (docs/theory.md §15, "Weak nodes"): the degrees of freedom (grid node,
/// velocity component) touched by a particle and not held by a wall, split into
///   - masters: the unknowns of (87) and (88a), and
///   - slaves: the components at weak nodes (nodes that particles cover to less than `weak_node_fraction` of a
///     cell's volume), whose value is extrapolated linearly from two master nodes further in along one grid axis,
///     u_A = 2 u_B - u_C (B = A + s e_k, C = A + 2 s e_k).
/// Every grid vector of the step is u = P y (y at the masters), and (87) and (88a) are solved in the Galerkin
/// form P^T M P v = P^T sum N pi and P^T R(P y) = 0. The energy identity (Prop. 3.1 with Cor. 3.2) holds for
/// any P, as both equations are restricted by the same P; P reproduces linear fields, so translations and
/// rotations stay in its range and both momenta are kept. Why: a node that one particle touches near its far
/// corner has a negligible mass but the particle's full stress gradient; its equation of (88a) then asks that
/// particle's stress to vanish in one direction, which Newton pursues until det F <= 0 (the stall of §15).

#include <array>
#include <utility>
#include <vector>

#include "mpm/grid/grid.hpp"

namespace mpm::implicit {

template <int Dim>
struct FreeDofs {
  /// A slave component: u[node][d] = sum c u[term node][d] (the term nodes are masters of component d).
  struct Slave {
    Index node = 0;
    int d = 0;
    std::vector<std::pair<Index, Real>> terms;
  };
  std::vector<Index> active;                       ///< grid nodes with mass, ascending
  std::vector<std::array<Index, Dim>> index;       ///< per grid node: its master dof per component, or -1
  std::vector<std::pair<Index, int>> dofs;         ///< per master dof: (grid node, component)
  std::array<std::vector<Index>, Dim> free_nodes;  ///< per component: the master nodes of that component
  std::array<std::vector<Slave>, Dim> slaves;      ///< per component, in the order they were made
  Index weak_kept = 0;  ///< weak components with no pair to extrapolate from (kept as masters)

  Index slave_count() const {
    Index n = 0;
    for (const auto& s : slaves) n += static_cast<Index>(s.size());
    return n;
  }

  /// u at the slaves of component d from u at the masters (u indexed by grid node).
  template <class U>
  void prolong(int d, U& u) const {
    for (const Slave& s : slaves[d]) {
      u[s.node] = 0;
      for (const auto& [node, c] : s.terms) u[s.node] += c * u[node];
    }
  }
  /// f at the masters += P^T f of the slaves of component d (f indexed by grid node).
  template <class U>
  void restrict_to_masters(int d, U& f) const {
    for (const Slave& s : slaves[d])
      for (const auto& [node, c] : s.terms) f[node] += c * f[s.node];
  }

  /// Splits the touched nodes' free components. `fraction`: per grid node, the volume of the particles
  /// weighted by N^A over the cell volume (1 for a node inside a filled region); `held(a, d)`: a wall holds
  /// that component. A weak component is extrapolated along the grid line (an axis or a diagonal) whose two
  /// nodes are best covered; first from two strong nodes, then, pass by pass, from nodes already resolved
  /// (a slave's terms are expanded into masters). A weak component with no such line stays a master.
  template <class Held>
  void build(const GridGeometry<Dim>& g, const std::vector<char>& touched, const std::vector<Real>& fraction,
             Real weak_fraction, const Held& held) {
    const Index nodes = g.node_count();
    *this = FreeDofs{};
    index.assign(nodes, {});
    std::vector<std::array<char, Dim>> state(nodes, std::array<char, Dim>{});  // 0 none, 1 master, 2 slave, 3 weak
    std::vector<std::array<Index, Dim>> slave_at(nodes);
    for (Index a = 0; a < nodes; ++a) {
      index[a].fill(-1);
      if (!touched[a]) continue;
      active.push_back(a);
      for (int d = 0; d < Dim; ++d)
        if (!held(a, d)) state[a][d] = fraction[a] < weak_fraction ? 3 : 1;
    }
    for (Index a : active)
      for (int d = 0; d < Dim; ++d)
        if (state[a][d] == 1) {
          index[a][d] = static_cast<Index>(dofs.size());
          dofs.emplace_back(a, d);
          free_nodes[d].push_back(a);
        }
    for (bool strong_only : {true, false})
      for (bool progress = true; progress;) {
        progress = false;
        for (Index a : active)
          for (int d = 0; d < Dim; ++d) {
            if (state[a][d] != 3) continue;
            const auto [b, c] = best_line(g, a, d, fraction, state, strong_only);
            if (b < 0) continue;
            Slave s{a, d, {}};
            add_terms(s.terms, b, d, Real(2), state, slave_at);
            add_terms(s.terms, c, d, Real(-1), state, slave_at);
            slave_at[a][d] = static_cast<Index>(slaves[d].size());
            slaves[d].push_back(std::move(s));
            state[a][d] = 2;
            progress = !strong_only;  // the strong pass needs one sweep: its lines never change
          }
      }
    for (Index a : active)  // the rest: masters after all
      for (int d = 0; d < Dim; ++d)
        if (state[a][d] == 3) {
          ++weak_kept;
          index[a][d] = static_cast<Index>(dofs.size());
          dofs.emplace_back(a, d);
          free_nodes[d].push_back(a);
        }
  }

 private:
  /// The grid line (B, C) = (A + s, A + 2 s), s in {-1, 0, 1}^Dim \ {0}, with both nodes resolved for component d
  /// (masters; also slaves unless strong_only) that is best covered (largest smaller fraction; the first on a
  /// tie), or (-1, -1).
  static std::pair<Index, Index> best_line(const GridGeometry<Dim>& g, Index a, int d,
                                           const std::vector<Real>& fraction,
                                           const std::vector<std::array<char, Dim>>& state, bool strong_only) {
    const auto ijk = g.node_indices(a);
    std::pair<Index, Index> best{-1, -1};
    Real best_score = -1;
    int directions = 1;
    for (int e = 0; e < Dim; ++e) directions *= 3;
    for (int o = 0; o < directions; ++o) {
      Index b = a, c = a;
      bool inside = true, zero = true;
      for (int e = 0, r = o; e < Dim; ++e, r /= 3) {
        const int s = r % 3 - 1;
        zero = zero && s == 0;
        inside = inside && ijk[e] + 2 * s >= 0 && ijk[e] + 2 * s < g.nodes[e];
        b += s * g.stride[e], c += 2 * s * g.stride[e];
      }
      if (zero || !inside) continue;
      const auto usable = [&](Index n) { return state[n][d] == 1 || (!strong_only && state[n][d] == 2); };
      if (!usable(b) || !usable(c)) continue;
      const Real score = std::min(fraction[b], fraction[c]);
      if (score > best_score) best_score = score, best = {b, c};
    }
    return best;
  }

  /// terms += w u[n][d], with a slave n expanded into its masters.
  void add_terms(std::vector<std::pair<Index, Real>>& terms, Index n, int d, Real w,
                 const std::vector<std::array<char, Dim>>& state, const std::vector<std::array<Index, Dim>>& slave_at) {
    if (state[n][d] == 1) return merge(terms, n, w);
    for (const auto& [m, c] : slaves[d][slave_at[n][d]].terms) merge(terms, m, w * c);
  }
  static void merge(std::vector<std::pair<Index, Real>>& terms, Index n, Real w) {
    for (auto& [m, c] : terms)
      if (m == n) {
        c += w;
        return;
      }
    terms.emplace_back(n, w);
  }
};

}  // namespace mpm::implicit
