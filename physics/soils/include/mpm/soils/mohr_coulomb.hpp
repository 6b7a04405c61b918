#pragma once
/// \file mohr_coulomb.hpp
/// The return mapping of the perfectly plastic Mohr-Coulomb pyramid with non-associated flow and a tension cut-off
/// (docs/theory.md §18, eqs. 18.8-18.11), in principal stresses sigma_1 >= sigma_2 >= sigma_3 (tension positive)
/// with the principal directions of the trial stress kept, as de Souza Neto, Peric & Owen, Computational Methods
/// for Plasticity (2008), §8.2: the return to the main plane, then to the edge the main return overshot (two
/// multipliers), then to the apex. Every surface is a plane in principal space here (perfect plasticity), so each
/// candidate return is one small linear solve (eq. 18.10); the candidates are tried in the book's order, the
/// cut-off plane p = T added, and the first that meets the Kuhn-Tucker conditions (multipliers >= 0, every surface
/// <= 0, the principal order kept) is taken. No smoothing of the edges.

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "mpm/soils/soil_params.hpp"

namespace mpm::soils {

class MohrCoulomb {
 public:
  static constexpr const char* key = "mohr_coulomb";

  explicit MohrCoulomb(const SoilParams& p) {
    const Real sp = std::sin(p.friction), sd = std::sin(p.dilation);
    bound_ = 2 * p.cohesion * std::cos(p.friction);
    const Real apex = sp > 0 ? p.cohesion * std::cos(p.friction) / sp : std::numeric_limits<Real>::infinity();
    cap_ = std::min(p.tension_cutoff, apex);
    // Planes a . sigma <= b and flow directions n (eqs. 18.8, 18.9): main (1, 3), edge A (2, 3), edge B (1, 2),
    // cut-off.
    normal_ = {Vec3(1 + sp, 0, -(1 - sp)), Vec3(0, 1 + sp, -(1 - sp)), Vec3(1 + sp, -(1 - sp), 0),
               Vec3::Constant(1.0 / 3)};
    const std::array<Vec3, 4> flow = {Vec3(1 + sd, 0, -(1 - sd)), Vec3(0, 1 + sd, -(1 - sd)),
                                      Vec3(1 + sd, -(1 - sd), 0), Vec3::Constant(1.0 / 3)};
    Mat3 D = Mat3::Constant(p.bulk_modulus - 2 * p.shear_modulus / 3);  // isotropic elasticity in principal space
    D.diagonal().array() += 2 * p.shear_modulus;
    for (std::size_t j = 0; j < 4; ++j) stiff_flow_[j] = D * flow[j];
    bounds_ = {bound_, bound_, bound_, cap_};
  }

  /// The Mohr-Coulomb yield function of a stress (sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin phi - 2 c cos phi
  /// (eq. 18.8), Pa.
  Real yield_function(const Mat3& sigma) const {
    const Vec3 s = sorted_eigenvalues(sigma);
    return normal_[0].dot(s) - bound_;
  }
  Real mean_stress_cap() const { return cap_; }

  /// The stress returned from the elastic trial stress (tension positive), Pa.
  Mat3 return_map(const Mat3& trial) const {
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(trial);
    // Eigen sorts ascending: principal values sigma_1 >= sigma_2 >= sigma_3 are columns 2, 1, 0.
    const Vec3 principal(eigen.eigenvalues()[2], eigen.eigenvalues()[1], eigen.eigenvalues()[0]);
    const Real tol = 1e-12 * (std::abs(bound_) + std::abs(cap_ == std::numeric_limits<Real>::infinity() ? 0 : cap_) +
                              principal.cwiseAbs().maxCoeff());
    if (admissible(principal, tol)) return trial;
    const Vec3 returned = return_principal(principal, tol);
    Mat3 out = Mat3::Zero();
    for (int i = 0; i < 3; ++i) {
      const Vec3 n = eigen.eigenvectors().col(2 - i);
      out += returned[i] * n * n.transpose();
    }
    return out;
  }

 private:
  using Vec3 = Eigen::Matrix<Real, 3, 1>;

  static Vec3 sorted_eigenvalues(const Mat3& sigma) {
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(sigma, Eigen::EigenvaluesOnly);
    return {eigen.eigenvalues()[2], eigen.eigenvalues()[1], eigen.eigenvalues()[0]};
  }

  bool admissible(const Vec3& s, Real tol) const {
    for (std::size_t k = 0; k < 4; ++k)
      if (normal_[k].dot(s) - bounds_[k] > tol) return false;
    return true;
  }

  /// Candidate active sets in the order of de Souza Neto §8.2 (main plane; the edges; with the cut-off).
  Vec3 return_principal(const Vec3& trial, Real tol) const {
    static constexpr std::array<std::array<int, 3>, 7> sets = {
        {{0, -1, -1}, {0, 1, -1}, {0, 2, -1}, {3, -1, -1}, {0, 3, -1}, {0, 1, 3}, {0, 2, 3}}};
    for (const auto& set : sets) {
      const int n = set[1] < 0 ? 1 : (set[2] < 0 ? 2 : 3);
      if (cap_ == std::numeric_limits<Real>::infinity() &&
          std::find(set.begin(), set.begin() + n, 3) != set.begin() + n)
        continue;
      // M gamma = Phi_trial, M_ij = a_i . D n_j (eq. 18.10).
      Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3> M(n, n);
      Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, 3, 1> rhs(n);
      for (int i = 0; i < n; ++i) {
        const auto a = static_cast<std::size_t>(set[static_cast<std::size_t>(i)]);
        rhs[i] = normal_[a].dot(trial) - bounds_[a];
        for (int j = 0; j < n; ++j)
          M(i, j) = normal_[a].dot(stiff_flow_[static_cast<std::size_t>(set[static_cast<std::size_t>(j)])]);
      }
      const Eigen::FullPivLU<decltype(M)> lu(M);
      if (!lu.isInvertible()) continue;
      const auto gamma = lu.solve(rhs).eval();
      if ((gamma.array() < 0).any()) continue;
      Vec3 s = trial;
      for (int j = 0; j < n; ++j)
        s -= gamma[j] * stiff_flow_[static_cast<std::size_t>(set[static_cast<std::size_t>(j)])];
      if (s[0] + tol < s[1] || s[1] + tol < s[2] || !admissible(s, tol)) continue;
      return s;
    }
    return Vec3::Constant(cap_);  // the apex (eq. 18.11): the only admissible stress left
  }

  Real bound_ = 0;  ///< 2 c cos phi
  Real cap_ = 0;    ///< min(T, c cot phi)
  std::array<Vec3, 4> normal_;
  std::array<Vec3, 4> stiff_flow_;  ///< D n of each plane
  std::array<Real, 4> bounds_;
};

}  // namespace mpm::soils
