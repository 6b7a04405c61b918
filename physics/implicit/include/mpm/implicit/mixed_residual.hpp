#pragma once
/// \file mixed_residual.hpp
/// The residual of one implicit step (ref. 003 eqs. 88a-91; docs/theory.md §15), in the unknowns Delta phi at
/// the master degrees of freedom (grid node and velocity component, walls removed; the weak nodes' components
/// are slaves, u = P y, and the residual is P^T R: free_dofs.hpp):
///   R = 2 M (Delta phi - dt v_n) / dt^2 + F^int_{n+1/2} - F^ext                      (88a with 88b)
///   F^int,A = sum_pt (F_{n+1/2} S^h) F_n^T grad_n N^A Omega_0                      (89a)
///   F^ext,A = sum_pt m b N^A                                                        (89b, gravity)
/// per point, with the stencil at x_n: f = 1 + grad_n Delta phi, F_{n+1} = f F_n (91); the material's trial
/// update at F_{n+1} (pure, hencky_j2.hpp); S_algo^dev (81)-(83) and D_C J (discrete_gradient.hpp); per cell
/// (Q1/P0) theta_e = sum Delta J Omega_0 / sum Omega_0 (88d), Theta_{n+1} = Theta_n + theta_e (88e),
/// p_e = sum D_Theta U(Theta_n, Theta_{n+1}) Omega_0 / sum Omega_0 (88c); S^h = S_algo^dev + 2 p D_C J (90).
/// With volumetric: pointwise, Theta = J per point and p = D_Theta U(J_n, J_{n+1}).
/// The per-point work runs in parallel into per-point slots; every sum (cells, nodes) runs serially in point
/// order: the same bits for any thread count.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

#include "mpm/core/parallel_chunks.hpp"
#include "mpm/implicit/consistent_mass.hpp"
#include "mpm/implicit/free_dofs.hpp"
#include "mpm/implicit/implicit_options.hpp"
#include "mpm/implicit/nonlinear_problem.hpp"
#include "mpm/implicit/step_points.hpp"
#include "mpm/plasticity/log_volumetric_energy.hpp"

namespace mpm::implicit {

/// det(1 + H) - 1 without the cancellation of det(1 + H) - 1 for small H: tr H + I_2(H) + det H.
inline Real det_one_plus_minus_one(const Mat3& H) {
  const Real tr = H.trace();
  const Real i2 = 0.5 * (tr * tr - (H * H).trace());
  return tr + i2 + H.determinant();
}

template <int Dim>
class MixedResidual final : public NonlinearProblem {
 public:
  static constexpr int count = StepPoints<Dim>::count;
  using Update = plasticity::HenckyJ2Update<Dim>;

  MixedResidual(const StepPoints<Dim>& points, const ConsistentMass<Dim>& mass, const FreeDofs<Dim>& dofs,
                const GridGeometry<Dim>& g, const std::vector<VecU<Dim>>& v_n, const std::vector<VecU<Dim>>& f_ext,
                Real dt, VolumetricMode volumetric)
      : pts_(points), M_(mass), dofs_(dofs), g_(g), v_n_(v_n), f_ext_(f_ext), dt_(dt), volumetric_(volumetric) {
    const Index n = points.size();
    F1_.resize(n), S_algo_.resize(n), DCJ_.resize(n), dJ_.resize(n), theta1_.resize(n), pressure_.resize(n);
    update_.resize(n), P_.resize(n);
    dphi_.assign(g.node_count(), VecU<Dim>::Zero());
    inertia_.assign(g.node_count(), VecU<Dim>::Zero());
    force_.assign(g.node_count(), VecU<Dim>::Zero());
    lag_.assign(g.node_count(), VecU<Dim>::Zero());
    full_.assign(g.node_count(), VecU<Dim>::Zero());
    Index cells = 1;
    for (int d = 0; d < Dim; ++d) cells *= g.nodes[d];  // indexed by the lower node: node-sized is enough
    cell_volume_.assign(cells, 0), cell_dJ_.assign(cells, 0), cell_pD_.assign(cells, 0);
    build_coupling();
    Real h = g.h[0];
    for (int d = 1; d < Dim; ++d) h = std::min<Real>(h, g.h[d]);
    unknown_scale_ = 1e-2 * h;
  }

  Index size() const override { return static_cast<Index>(dofs_.dofs.size()); }
  const std::vector<std::vector<Index>>& column_groups() const override { return groups_; }
  const std::vector<std::vector<Index>>& column_rows() const override { return rows_; }
  Real unknown_scale() const override { return unknown_scale_; }

  bool residual(const Vector& x, Vector& r) override {
    scatter(x);
    if (!evaluate_points()) return false;
    assemble_forces();
    // inertia 2 M (Delta phi - dt v_n) / dt^2 (88a with 88b); Delta phi and v_n are zero at held components
    const Real c = 2 / (dt_ * dt_);
    for (Index a : dofs_.active) lag_[a] = dphi_[a] - dt_ * v_n_[a];
    M_.multiply(dofs_.active, lag_, inertia_);
    for (Index a : dofs_.active) full_[a] = c * inertia_[a] + force_[a] - f_ext_[a];
    for (int d = 0; d < Dim; ++d)  // P^T R: a slave's equation goes to the masters it is extrapolated from
      for (const auto& s : dofs_.slaves[d])
        for (const auto& [node, w] : s.terms) full_[node][d] += w * full_[s.node][d];
    r.resize(size());
    for (Index k = 0; k < size(); ++k) r[k] = full_[dofs_.dofs[k].first][dofs_.dofs[k].second];
    return r.allFinite();
  }

  /// Delta phi on the grid (zero at held components) of the last residual.
  const std::vector<VecU<Dim>>& increment() const { return dphi_; }
  /// Per point, of the last residual: F_{n+1}, the material's update, Theta_{n+1}, the mixed pressure p.
  const std::vector<Mat3>& deformation_gradient() const { return F1_; }
  const std::vector<Update>& update() const { return update_; }
  const std::vector<Real>& mixed_volume() const { return theta1_; }
  const std::vector<Real>& pressure() const { return pressure_; }

  /// The grid vector of an unknown vector (held components zero).
  void scatter(const Vector& x) {
    for (Index a : dofs_.active) dphi_[a].setZero();
    for (Index k = 0; k < size(); ++k) dphi_[dofs_.dofs[k].first][dofs_.dofs[k].second] = x[k];
    for (int d = 0; d < Dim; ++d)
      for (const auto& s : dofs_.slaves[d]) {
        dphi_[s.node][d] = 0;
        for (const auto& [node, c] : s.terms) dphi_[s.node][d] += c * dphi_[node][d];
      }
  }

 private:
  /// Pass 1 (parallel, per point): F_{n+1}, Delta J, the material's trial update, S_algo^dev, D_C J; then the
  /// cells (serial) and pass 2 (parallel): S^h and P = F_{n+1/2} S^h F_n^T Omega_0.
  bool evaluate_points() {
    std::atomic<bool> ok{true};
    const Index n = pts_.size();
    parallel_chunks(Index{0}, n, 256, [&](Index chunk_begin, Index chunk_end) {
      for (Index i = chunk_begin; i != chunk_end; ++i)
        if (!evaluate_point(i)) ok.store(false, std::memory_order_relaxed);
    });
    if (!ok.load()) return false;
    if (!mixed_pressures()) return false;
    parallel_chunks(Index{0}, n, 256, [&](Index chunk_begin, Index chunk_end) {
      for (Index i = chunk_begin; i != chunk_end; ++i) {
        const Mat3 S_h = plasticity::algorithmic_stress(S_algo_[i], pressure_[i], DCJ_[i]);  // (90)
        P_[i] = pts_.volume0[i] * (0.5 * (pts_.F_n[i] + F1_[i]) * S_h * pts_.F_n[i].transpose());
      }
    });
    return true;
  }

  bool evaluate_point(Index i) {
    Mat3 H = Mat3::Zero();  // grad_n Delta phi at x_n (91)
    for (int a = 0; a < count; ++a)
      H.template topLeftCorner<Dim, Dim>() += Vec<Dim>(dphi_[pts_.node[i][a]]) * Vec<Dim>(pts_.grad[i][a]).transpose();
    if (pts_.axisymmetric)  // the hoop stretch increment Delta phi_r / r (review eq. G.4)
      for (int a = 0; a < count; ++a) H(2, 2) += pts_.hoop[i][a] * dphi_[pts_.node[i][a]][0];
    const Real dj = det_one_plus_minus_one(H);
    if (!(1 + dj > 0)) return false;
    const Mat3& F_n = pts_.F_n[i];
    F1_[i] = (Mat3::Identity() + H) * F_n;
    const Real J_n = pts_.J_n[i], J1 = J_n * (1 + dj);
    dJ_[i] = J_n * dj;
    update_[i] = plasticity::HenckyJ2::evaluate<Dim>(*pts_.params[i], *pts_.state_n[i], F1_[i], dt_);
    const Update& u = update_[i];
    const Mat3 dC = plasticity::right_cauchy_green_increment(F_n, H);
    S_algo_[i] = plasticity::algorithmic_deviatoric_stress(pts_.S_n[i], plasticity::pull_back(F1_[i], u.dev_kirchhoff),
                                                           pts_.W_n[i], u.stored_energy, u.dissipation, pts_.C_n[i],
                                                           dC);  // (81)-(83)
    DCJ_[i] = plasticity::jacobian_discrete_derivative(pts_.C_n[i], dC, J_n, J1);
    return S_algo_[i].allFinite() && DCJ_[i].allFinite();
  }

  /// (88c)-(88e) per cell, or Theta = J per point; false when a Theta_{n+1} <= 0.
  bool mixed_pressures() {
    const Index n = pts_.size();
    if (volumetric_ == VolumetricMode::pointwise) {
      for (Index i = 0; i < n; ++i) {
        theta1_[i] = pts_.theta_n[i] + dJ_[i];
        if (!(theta1_[i] > 0)) return false;
        const plasticity::LogVolumetricEnergy U{pts_.params[i]->bulk_modulus};
        pressure_[i] = U.discrete_derivative(pts_.theta_n[i], theta1_[i]);
      }
      return true;
    }
    for (Index i = 0; i < n; ++i) cell_volume_[pts_.cell[i]] = cell_dJ_[pts_.cell[i]] = cell_pD_[pts_.cell[i]] = 0;
    for (Index i = 0; i < n; ++i) {
      cell_volume_[pts_.cell[i]] += pts_.volume0[i];
      cell_dJ_[pts_.cell[i]] += pts_.volume0[i] * dJ_[i];  // (88d)
    }
    for (Index i = 0; i < n; ++i) {
      const Index e = pts_.cell[i];
      theta1_[i] = pts_.theta_n[i] + cell_dJ_[e] / cell_volume_[e];  // (88e)
      if (!(theta1_[i] > 0)) return false;
      const plasticity::LogVolumetricEnergy U{pts_.params[i]->bulk_modulus};
      cell_pD_[e] += pts_.volume0[i] * U.discrete_derivative(pts_.theta_n[i], theta1_[i]);  // (88c)
    }
    for (Index i = 0; i < n; ++i) pressure_[i] = cell_pD_[pts_.cell[i]] / cell_volume_[pts_.cell[i]];
    return true;
  }

  /// F^int (89a), serially in point order.
  void assemble_forces() {
    for (Index a : dofs_.active) force_[a].setZero();
    for (Index i = 0; i < pts_.size(); ++i) {
      const Mat<Dim> P = P_[i].template topLeftCorner<Dim, Dim>();
      for (int a = 0; a < count; ++a) force_[pts_.node[i][a]] += P * Vec<Dim>(pts_.grad[i][a]);
      if (pts_.axisymmetric)  // the hoop term of (89a): P_tt T^A on the radial component (review eq. G.2)
        for (int a = 0; a < count; ++a) force_[pts_.node[i][a]][0] += P_[i](2, 2) * pts_.hoop[i][a];
    }
  }

  /// The Jacobian's sparsity and column groups. A master dof j moves Delta phi at its node and at the slaves
  /// extrapolated from it; the full residual changes at every free component of the nodes sharing a cell with
  /// those; P^T sends a slave's row to its masters. Columns that share no row form a group (greedy colouring
  /// in dof order: 3^Dim x Dim groups without slaves, as nodes three apart never share a row).
  void build_coupling() {
    const Index n = size();
    const Index nodes = g_.node_count();
    std::vector<std::vector<Index>> moved(nodes);  // per node: the master dofs that move it
    for (Index k = 0; k < n; ++k) moved[dofs_.dofs[k].first].push_back(k);
    std::vector<std::array<std::vector<std::pair<Index, Real>>, Dim>> slave_terms(nodes);
    for (int d = 0; d < Dim; ++d)
      for (const auto& s : dofs_.slaves[d])
        for (const auto& [node, w] : s.terms) {
          moved[s.node].push_back(dofs_.index[node][d]);
          slave_terms[s.node][d].emplace_back(node, w);
        }
    // per master dof: the nodes whose Delta phi it moves, then the rows of P^T R it reaches
    std::vector<std::vector<Index>> touches(n);
    for (Index a = 0; a < nodes; ++a)
      for (Index k : moved[a]) touches[k].push_back(a);
    rows_.assign(n, {});
    for (Index k = 0; k < n; ++k) {
      std::vector<Index>& rows = rows_[k];
      for (Index a : touches[k])
        for_each_neighbour(a, [&](Index b) {
          for (int c = 0; c < Dim; ++c) {
            if (dofs_.index[b][c] >= 0) rows.push_back(dofs_.index[b][c]);
            for (const auto& [node, w] : slave_terms[b][c]) rows.push_back(dofs_.index[node][c]);
          }
        });
      std::sort(rows.begin(), rows.end());
      rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    }
    // greedy colouring: a column joins the first group none of whose columns shares one of its rows
    groups_.clear();
    std::vector<std::vector<char>> used;  // per group: the rows its columns reach
    for (Index k = 0; k < n; ++k) {
      std::size_t colour = 0;
      for (; colour < groups_.size(); ++colour)
        if (std::none_of(rows_[k].begin(), rows_[k].end(), [&](Index r) { return used[colour][r] != 0; })) break;
      if (colour == groups_.size()) groups_.emplace_back(), used.emplace_back(n, 0);
      groups_[colour].push_back(k);
      for (Index r : rows_[k]) used[colour][r] = 1;
    }
  }

  /// Calls f for every grid node within one cell of node a on every axis (a included).
  template <class F>
  void for_each_neighbour(Index a, F&& f) const {
    const auto ijk = g_.node_indices(a);
    for (int o = 0; o < ConsistentMass<Dim>::neighbours; ++o) {
      Index b = 0;
      bool inside = true;
      for (int e = 0, r = o; e < Dim; ++e, r /= 3) {
        const int j = ijk[e] + r % 3 - 1;
        inside = inside && j >= 0 && j < g_.nodes[e];
        b += j * g_.stride[e];
      }
      if (inside) f(b);
    }
  }

  const StepPoints<Dim>& pts_;
  const ConsistentMass<Dim>& M_;
  const FreeDofs<Dim>& dofs_;
  const GridGeometry<Dim>& g_;
  const std::vector<VecU<Dim>>& v_n_;
  const std::vector<VecU<Dim>>& f_ext_;
  Real dt_;
  VolumetricMode volumetric_;
  Real unknown_scale_ = 0;
  std::vector<Mat3> F1_, S_algo_, DCJ_, P_;
  std::vector<Real> dJ_, theta1_, pressure_;
  std::vector<Update> update_;
  std::vector<VecU<Dim>> dphi_, inertia_, force_, lag_, full_;
  std::vector<Real> cell_volume_, cell_dJ_, cell_pD_;
  std::vector<std::vector<Index>> groups_, rows_;
};

}  // namespace mpm::implicit
