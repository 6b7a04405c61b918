#pragma once
/// \file polar_decomposition.hpp
/// Rotation R of the polar decomposition F = R U (review App. B.3, objectivity), in closed form:
/// no iteration, no SVD, so that it costs about as much as a few 3x3 products per particle.
///   3D: eigenvalues mu_i of C = F^T F by the trigonometric formula for symmetric 3x3 matrices, the
///       invariants I, II, III of U = sqrt(C) from lambda_i = sqrt(mu_i) (III = det F), then
///       U = [-C^2 + (I^2 - II) C + I III 1] / (I II - III) and U^-1 = [C - I U + II 1] / III
///       (Cayley-Hamilton for U; Hoger & Carlson 1984), and R = F U^-1. The denominator
///       I II - III = (l1 + l2)(l2 + l3)(l3 + l1) never vanishes, so repeated stretches (U = 1, the
///       common elastic case) are not a special case.
///   2D (plane strain, F_zz = 1): R is the rotation about z by atan2(F_yx - F_xy, F_xx + F_yy).
///   1D: R = 1.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mpm/plasticity/lanes.hpp"

namespace mpm::plasticity {

/// R of F = R U for a 3x3 F with det F > 0.
inline Mat3 polar_rotation(const Mat3& F) {
  const Mat3 C = F.transpose() * F;
  const Real q = C.trace() / 3;
  Mat3 B = C;
  B.diagonal().array() -= q;
  const Real p2 = B.squaredNorm() / 6;
  Real mu1 = q, mu2 = q, mu3 = q;
  if (p2 > 1e-30 * q * q) {
    const Real p = std::sqrt(p2);
    const Real r = std::clamp(B.determinant() / (2 * p2 * p), Real(-1), Real(1));
    const Real phi = std::acos(r) / 3;
    const Real c = std::cos(phi), s = std::sqrt(std::max(Real(0), 1 - c * c));
    mu1 = q + 2 * p * c;                                           // largest
    mu3 = q + 2 * p * (-0.5 * c - 0.5 * std::numbers::sqrt3 * s);  // cos(phi + 2 pi / 3): smallest
    mu2 = 3 * q - mu1 - mu3;
  }
  const Real l1 = std::sqrt(std::max(mu1, Real(0))), l2 = std::sqrt(std::max(mu2, Real(0))),
             l3 = std::sqrt(std::max(mu3, Real(0)));
  const Real I = l1 + l2 + l3, II = l1 * l2 + l2 * l3 + l3 * l1, III = F.determinant();
  Mat3 U = ((I * I - II) * C - C * C) / (I * II - III);
  U.diagonal().array() += I * III / (I * II - III);
  Mat3 U_inv = C - I * U;
  U_inv.diagonal().array() += II;
  return F * (U_inv / III);
}

/// Rotation matrix R of the unit quaternion q = (w, x, y, z), for one point or a pack (lanes.hpp).
template <class T>
inline void rotation_matrix(const T q[4], T R[3][3]) {
  const T &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  R[0][0] = 1 - 2 * (y * y + z * z);
  R[0][1] = 2 * (x * y - w * z);
  R[0][2] = 2 * (x * z + w * y);
  R[1][0] = 2 * (x * y + w * z);
  R[1][1] = 1 - 2 * (x * x + z * z);
  R[1][2] = 2 * (y * z - w * x);
  R[2][0] = 2 * (x * z - w * y);
  R[2][1] = 2 * (y * z + w * x);
  R[2][2] = 1 - 2 * (x * x + y * y);
}

inline Mat3 rotation_of(const Real q[4]) {
  Real R[3][3];
  rotation_matrix(q, R);
  Mat3 out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out(i, j) = R[i][j];
  return out;
}

/// s <- R s R^T for a symmetric s stored as (xx, yy, zz, xy, yz, xz) (written out: 45 multiply-adds).
template <class T>
inline void rotate_symmetric(const T R[3][3], T s[6]) {
  const T S[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  T M[3][3];  // M = S R^T
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M[i][j] = S[i][0] * R[j][0] + S[i][1] * R[j][1] + S[i][2] * R[j][2];
  auto out = [&](int i, int j) -> T { return R[i][0] * M[0][j] + R[i][1] * M[1][j] + R[i][2] * M[2][j]; };
  s[0] = out(0, 0);
  s[1] = out(1, 1);
  s[2] = out(2, 2);
  s[3] = out(0, 1);
  s[4] = out(1, 2);
  s[5] = out(0, 2);
}

/// Newton iterations for R of F = R U (3D), started from the previous step's rotation `q` (unit
/// quaternion, updated in place): with A = R^T F = S + K (symmetric + skew, k = axial K), the correction
/// R <- R exp(theta x) that makes R^T F symmetric solves, to first order, ((tr S) 1 - S) theta = 2 k; the
/// matrix has eigenvalues l_i + l_j > 0. Convergence is quadratic and the rotation of one explicit step is
/// small, so one or two iterations reach |theta| < `tolerance` (the error left is about |theta|^2). R is
/// orthogonal to round-off whatever the number of iterations (q is normalised). A lane stops when it has
/// converged; the returned mask marks the lanes that did not within `max_iterations` or met a degenerate
/// F (their q is then unusable and must come from the closed form).
template <class T>
inline MaskOf<T> polar_newton(const T F[3][3], T q[4], Real tolerance, int max_iterations) {
  MaskOf<T> active = lanes::splat_mask<T>(true), failed = lanes::splat_mask<T>(false);
  for (int it = 0; it < max_iterations; ++it) {
    T R[3][3], A[3][3];
    rotation_matrix(q, R);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) A[i][j] = R[0][i] * F[0][j] + R[1][i] * F[1][j] + R[2][i] * F[2][j];
    const T k0 = 0.5 * (A[2][1] - A[1][2]), k1 = 0.5 * (A[0][2] - A[2][0]), k2 = 0.5 * (A[1][0] - A[0][1]);
    const T tr = A[0][0] + A[1][1] + A[2][2];
    const T m00 = tr - A[0][0], m11 = tr - A[1][1], m22 = tr - A[2][2];
    const T m01 = -0.5 * (A[0][1] + A[1][0]), m02 = -0.5 * (A[0][2] + A[2][0]), m12 = -0.5 * (A[1][2] + A[2][1]);
    // theta = 2 M^-1 k by the adjugate of the symmetric M
    const T a00 = m11 * m22 - m12 * m12, a01 = m02 * m12 - m01 * m22, a02 = m01 * m12 - m02 * m11;
    const T a11 = m00 * m22 - m02 * m02, a12 = m01 * m02 - m00 * m12, a22 = m00 * m11 - m01 * m01;
    const T det = m00 * a00 + m01 * a01 + m02 * a02;
    const MaskOf<T> regular = det > 0;
    failed = lanes::either(failed, lanes::both(active, lanes::negate(regular)));
    active = lanes::both(active, regular);
    const T f = 2 / det;
    const T t0 = f * (a00 * k0 + a01 * k1 + a02 * k2), t1 = f * (a01 * k0 + a11 * k1 + a12 * k2),
            t2 = f * (a02 * k0 + a12 * k1 + a22 * k2);
    // q <- q (x) (1, theta / 2), normalised
    const T h0 = 0.5 * t0, h1 = 0.5 * t1, h2 = 0.5 * t2;
    const T w = q[0] - q[1] * h0 - q[2] * h1 - q[3] * h2;
    const T x = q[1] + q[0] * h0 + q[2] * h2 - q[3] * h1;
    const T y = q[2] + q[0] * h1 + q[3] * h0 - q[1] * h2;
    const T z = q[3] + q[0] * h2 + q[1] * h1 - q[2] * h0;
    const T n = 1 / lanes::sqrt(T(w * w + x * x + y * y + z * z));
    const T next[4] = {w * n, x * n, y * n, z * n};
    for (int c = 0; c < 4; ++c) q[c] = lanes::select(active, next[c], q[c]);
    const MaskOf<T> converged = t0 * t0 + t1 * t1 + t2 * t2 < tolerance * tolerance;
    active = lanes::both(active, lanes::negate(converged));
    if (!lanes::any(active)) return failed;
  }
  return lanes::either(failed, active);
}

/// R of F = R U (3D) by polar_newton from the previous rotation `q` (updated in place); after
/// `max_iterations`, or for a degenerate F, the closed form above is used and q reset.
/// polar_update_warm only updates q; polar_rotation_warm also returns R.
inline void polar_update_warm(const Real F[3][3], Real q[4], Real tolerance = 1e-3, int max_iterations = 8) {
  if (!polar_newton<Real>(F, q, tolerance, max_iterations)) return;
  Mat3 Fm;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Fm(i, j) = F[i][j];
  const Mat3 R = polar_rotation(Fm);
  const Real w = 0.5 * std::sqrt(std::max(Real(0), 1 + R.trace()));
  if (w > 0.1) {
    q[0] = w;
    q[1] = (R(2, 1) - R(1, 2)) / (4 * w);
    q[2] = (R(0, 2) - R(2, 0)) / (4 * w);
    q[3] = (R(1, 0) - R(0, 1)) / (4 * w);
  } else {  // rotation by nearly pi: from the largest diagonal entry
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
}

inline void polar_update_warm(const Mat3& F, Real q[4], Real tolerance = 1e-3, int max_iterations = 8) {
  Real Fa[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Fa[i][j] = F(i, j);
  polar_update_warm(Fa, q, tolerance, max_iterations);
}

/// The same for a pack of points: the lanes polar_newton gives up on are redone one by one by the scalar
/// version, from their starting rotation, so that every lane gets exactly the scalar result's method.
inline void polar_update_warm(const Pack F[3][3], Pack q[4], Real tolerance = 1e-3, int max_iterations = 8) {
  const Pack q_start[4] = {q[0], q[1], q[2], q[3]};
  const PackMask failed = polar_newton<Pack>(F, q, tolerance, max_iterations);
  if (!failed.any()) return;
  for (int l = 0; l < lane_count; ++l) {
    if (!failed[l]) continue;
    Real Fl[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Fl[i][j] = F[i][j][l];
    Real ql[4] = {q_start[0][l], q_start[1][l], q_start[2][l], q_start[3][l]};
    polar_update_warm(Fl, ql, tolerance, max_iterations);
    for (int c = 0; c < 4; ++c) q[c][l] = ql[c];
  }
}

inline Mat3 polar_rotation_warm(const Mat3& F, Real q[4], Real tolerance = 1e-3, int max_iterations = 8) {
  polar_update_warm(F, q, tolerance, max_iterations);
  return rotation_of(q);
}

/// R of F = R U for the deformation gradient of a Dim-dimensional particle (plane strain in 2D,
/// uniaxial strain in 1D), as a 3x3 rotation.
template <int Dim>
inline Mat3 polar_rotation_of(const Mat<Dim>& F) {
  if constexpr (Dim == 1) {
    return Mat3::Identity();
  } else if constexpr (Dim == 2) {
    const Real c = F(0, 0) + F(1, 1), s = F(1, 0) - F(0, 1);
    const Real n = std::hypot(c, s);
    Mat3 R = Mat3::Identity();
    R(0, 0) = R(1, 1) = c / n;
    R(1, 0) = s / n;
    R(0, 1) = -s / n;
    return R;
  } else {
    return polar_rotation(F);
  }
}

}  // namespace mpm::plasticity
