#pragma once
/// \file symmetric_eigen.hpp
/// Spectral decomposition a = sum_A lambda_A m_A (x) m_A of a symmetric 3x3 tensor with the block structure
/// that `Dim` guarantees (ref. 003 eqs. 64-65 diagonalise b^e_tr this way; Remark 3.1 leaves the method open):
///   1D (uniaxial strain): a is diagonal, m_A are the axes;
///   2D (plane strain, and the axisymmetric mode with zz the hoop direction): an in-plane 2x2 block and zz,
///      the block in closed form (rotation angle by atan2, eigenvalues as Rayleigh quotients, both accurate to
///      round-off of |a| also for nearly equal eigenvalues);
///   3D: Eigen's iterative SelfAdjointEigenSolver (tridiagonalisation and implicit QR; the closed-form
///      computeDirect loses about half the digits of the eigenvectors when eigenvalues nearly coincide, which is
///      the common case b^e ~ 1 here).

#include <Eigen/Eigenvalues>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm::plasticity {

/// Eigenvalues and orthonormal eigenvectors (the columns of `vectors`, in the order of `values`).
struct SymmetricEigen {
  Vec3 values;
  Mat3 vectors;
};

/// The spectral decomposition of the symmetric `a`, whose entries outside the pattern of Dim are ignored.
template <int Dim>
inline SymmetricEigen symmetric_eigen(const Mat3& a) {
  SymmetricEigen e;
  if constexpr (Dim == 1) {
    e.values = a.diagonal();
    e.vectors.setIdentity();
  } else if constexpr (Dim == 2) {
    const Real theta = 0.5 * std::atan2(2 * a(0, 1), a(0, 0) - a(1, 1));
    const Real c = std::cos(theta), s = std::sin(theta);
    e.values[0] = c * c * a(0, 0) + 2 * c * s * a(0, 1) + s * s * a(1, 1);
    e.values[1] = s * s * a(0, 0) - 2 * c * s * a(0, 1) + c * c * a(1, 1);
    e.values[2] = a(2, 2);
    e.vectors << c, -s, 0, s, c, 0, 0, 0, 1;
  } else {
    const Eigen::SelfAdjointEigenSolver<Mat3> solver(a);
    e.values = solver.eigenvalues();
    e.vectors = solver.eigenvectors();
  }
  return e;
}

/// sum_A w_A m_A (x) m_A: the isotropic tensor function with principal values w on the eigenvectors of `e`.
inline Mat3 spectral_sum(const SymmetricEigen& e, const Vec3& w) {
  return e.vectors * w.asDiagonal() * e.vectors.transpose();
}

}  // namespace mpm::plasticity
