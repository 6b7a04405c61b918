#pragma once
/// \file corotational.hpp
/// The kinematics the user interfaces receive, per point: the Green-Naghdi rotation R and stretch U of F = R U
/// (README.md, "Frames"), and the conversions between 3x3 tensors and the component lists of the interfaces.
///   3D: R by Newton iterations started from the previous step's rotation (a unit quaternion), iterated to round-off
///       (the correction below 1e-13 rad), with an eigen-decomposition of C = F^T F as the fallback;
///   2D: the rotation about z, closed form atan2(F_yx - F_xy, F_xx + F_yy) (plane strain and axisymmetric alike:
///       the hoop stretch is a principal stretch);
///   1D: R = 1.

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm::user_material {

/// The rotation of the unit quaternion q = (w, x, y, z).
inline Mat3 rotation_of(const Real q[4]) {
  const Real w = q[0], x = q[1], y = q[2], z = q[3];
  Mat3 R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

/// The unit quaternion of a rotation matrix (Shepperd's method: the largest of w, x, y, z first).
inline void quaternion_of(const Mat3& R, Real q[4]) {
  const Real t = R.trace();
  if (t >= std::max({R(0, 0), R(1, 1), R(2, 2)})) {
    const Real s = 2 * std::sqrt(std::max(Real(0), 1 + t));
    q[0] = 0.25 * s;
    q[1] = (R(2, 1) - R(1, 2)) / s;
    q[2] = (R(0, 2) - R(2, 0)) / s;
    q[3] = (R(1, 0) - R(0, 1)) / s;
  } else {
    int i = 0;
    if (R(1, 1) > R(i, i)) i = 1;
    if (R(2, 2) > R(i, i)) i = 2;
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const Real s = 2 * std::sqrt(std::max(Real(0), 1 + R(i, i) - R(j, j) - R(k, k)));
    q[0] = (R(k, j) - R(j, k)) / s;
    q[1 + i] = 0.25 * s;
    q[1 + j] = (R(j, i) + R(i, j)) / s;
    q[1 + k] = (R(k, i) + R(i, k)) / s;
  }
  const Real n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int c = 0; c < 4; ++c) q[c] /= n;
}

/// R of F = R U by the eigen-decomposition of C = F^T F (U = V sqrt(L) V^T, R = F U^-1); det F > 0.
inline Mat3 polar_rotation_eigen(const Mat3& F) {
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(F.transpose() * F);
  const Vec<3> stretch = eigen.eigenvalues().cwiseMax(Real(0)).cwiseSqrt();
  const Mat3& V = eigen.eigenvectors();
  return F * V * stretch.cwiseInverse().asDiagonal() * V.transpose();
}

/// R of F = R U (3D) by Newton iterations from the rotation `q` (updated in place): with A = R^T F = S + K, the
/// correction R <- R exp(theta x) that makes R^T F symmetric solves ((tr S) 1 - S) theta = 2 k (k the axial
/// vector of K) to first order; quadratic convergence, stopped when |theta| < 1e-13 (the error left is round-off).
/// Falls back to polar_rotation_eigen when the iteration meets a degenerate F or does not converge in 30 steps.
inline Mat3 polar_rotation_3d(const Mat3& F, Real q[4]) {
  for (int it = 0; it < 30; ++it) {
    const Mat3 A = rotation_of(q).transpose() * F;
    const Vec<3> k(0.5 * (A(2, 1) - A(1, 2)), 0.5 * (A(0, 2) - A(2, 0)), 0.5 * (A(1, 0) - A(0, 1)));
    const Mat3 S = 0.5 * (A + A.transpose());
    const Mat3 M = S.trace() * Mat3::Identity() - S;
    const Real det = M.determinant();
    if (!(det > 0)) break;
    const Vec<3> theta = 2 * (M.inverse() * k);
    const Real h0 = 0.5 * theta[0], h1 = 0.5 * theta[1], h2 = 0.5 * theta[2];
    const Real w = q[0] - q[1] * h0 - q[2] * h1 - q[3] * h2;
    const Real x = q[1] + q[0] * h0 + q[2] * h2 - q[3] * h1;
    const Real y = q[2] + q[0] * h1 + q[3] * h0 - q[1] * h2;
    const Real z = q[3] + q[0] * h2 + q[1] * h1 - q[2] * h0;
    const Real n = 1 / std::sqrt(w * w + x * x + y * y + z * z);
    q[0] = w * n;
    q[1] = x * n;
    q[2] = y * n;
    q[3] = z * n;
    if (theta.squaredNorm() < 1e-26) return rotation_of(q);
  }
  const Mat3 R = polar_rotation_eigen(F);
  quaternion_of(R, q);
  return rotation_of(q);
}

/// The rotation about z of an in-plane F (2D: plane strain or axisymmetric), closed form.
inline Mat3 polar_rotation_2d(const Mat3& F) {
  const Real a = F(0, 0) + F(1, 1), b = F(1, 0) - F(0, 1);
  const Real n = 1 / std::hypot(a, b);
  const Real c = a * n, s = b * n;
  Mat3 R = Mat3::Identity();
  R(0, 0) = R(1, 1) = c;
  R(1, 0) = s;
  R(0, 1) = -s;
  return R;
}

/// The symmetric part of a 3x3 matrix.
inline Mat3 symmetric_part(const Mat3& A) { return 0.5 * (A + A.transpose()); }

/// Index pairs of the symmetric components, VUMAT and C order: 11, 22, 33, 12, 23, 31.
inline constexpr int vumat_pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
/// UMAT (Abaqus/Standard) order: 11, 22, 33, 12, 13, 23.
inline constexpr int umat_pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
/// The nonsymmetric components of a VUMAT defgrad: 3D 11, 22, 33, 12, 23, 31, 21, 32, 13; 2D 11, 22, 33, 12, 21.
inline constexpr int defgrad_pairs_3d[9][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}, {1, 0}, {2, 1}, {0, 2}};
inline constexpr int defgrad_pairs_2d[5][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 0}};

/// The symmetric 3x3 matrix of `n` components `c(k)` in the order `pairs` (the others 0); `shear` divides the
/// shear components (2 for engineering strains, else 1).
template <class Get>
Mat3 symmetric_from(const int (*pairs)[2], int n, Get c, Real shear = 1) {
  Mat3 m = Mat3::Zero();
  for (int k = 0; k < n; ++k) {
    const Real v = k < 3 ? c(k) : c(k) / shear;
    m(pairs[k][0], pairs[k][1]) = v;
    m(pairs[k][1], pairs[k][0]) = v;
  }
  return m;
}

}  // namespace mpm::user_material
