#pragma once
/// \file types.hpp
/// Scalar, vector and tensor types shared by the whole library.
/// Dimension is a compile-time parameter (1, 2 or 3). 1D means uniaxial strain and 2D means plane
/// strain: the out-of-plane stretch is 1 and the out-of-plane stress is kept (see SymTensor).

#include <Eigen/Core>
#include <Eigen/LU>
#include <cstdint>

namespace mpm {

using Real = double;
using Index = std::int64_t;

/// A set of grid nodes, one byte per node (1: in the set); without a mask, every node. A distributed run's rank owns
/// such a set (TileHalo::owned_nodes); sums over nodes take the owned ones so that the ranks' sums add up to one.
struct NodeMask {
  const std::uint8_t* mask = nullptr;
  bool contains(Index n) const { return mask == nullptr || mask[n] != 0; }
};

template <int Dim>
using Vec = Eigen::Matrix<Real, Dim, 1>;
template <int Dim>
using Mat = Eigen::Matrix<Real, Dim, Dim>;
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;

/// Symmetric 3x3 tensor stored with only the components that can be non-zero in `Dim` dimensions:
/// 1D (uniaxial strain): xx, yy, zz; 2D (plane strain): xx, yy, zz, xy; 3D: xx, yy, zz, xy, yz, xz.
/// Stress is stored this way so that a 2D particle carries 4 numbers, not 9.
template <int Dim>
struct SymTensor {
  static constexpr int size = Dim == 1 ? 3 : (Dim == 2 ? 4 : 6);
  Real c[size] = {};

  /// Full 3x3 matrix (zeros where the dimension forces them).
  Mat3 full() const {
    Mat3 m = Mat3::Zero();
    m(0, 0) = c[0];
    m(1, 1) = c[1];
    m(2, 2) = c[2];
    if constexpr (Dim >= 2) m(0, 1) = m(1, 0) = c[3];
    if constexpr (Dim == 3) {
      m(1, 2) = m(2, 1) = c[4];
      m(0, 2) = m(2, 0) = c[5];
    }
    return m;
  }
  /// Packs a symmetric 3x3 matrix (components that must vanish in `Dim` are dropped).
  static SymTensor from(const Mat3& m) {
    SymTensor s;
    s.c[0] = m(0, 0);
    s.c[1] = m(1, 1);
    s.c[2] = m(2, 2);
    if constexpr (Dim >= 2) s.c[3] = 0.5 * (m(0, 1) + m(1, 0));
    if constexpr (Dim == 3) {
      s.c[4] = 0.5 * (m(1, 2) + m(2, 1));
      s.c[5] = 0.5 * (m(0, 2) + m(2, 0));
    }
    return s;
  }
  /// Overwrites the in-plane Dim x Dim block (symmetrised); out-of-plane components are kept.
  void set_block(const Mat<Dim>& m) {
    c[0] = m(0, 0);
    if constexpr (Dim >= 2) {
      c[1] = m(1, 1);
      c[3] = 0.5 * (m(0, 1) + m(1, 0));
    }
    if constexpr (Dim == 3) {
      c[2] = m(2, 2);
      c[4] = 0.5 * (m(1, 2) + m(2, 1));
      c[5] = 0.5 * (m(0, 2) + m(2, 0));
    }
  }
  /// The in-plane Dim x Dim block, which is all the internal force needs.
  Mat<Dim> block() const {
    Mat<Dim> m;
    m(0, 0) = c[0];
    if constexpr (Dim >= 2) {
      m(1, 1) = c[1];
      m(0, 1) = m(1, 0) = c[3];
    }
    if constexpr (Dim == 3) {
      m(2, 2) = c[2];
      m(1, 2) = m(2, 1) = c[4];
      m(0, 2) = m(2, 0) = c[5];
    }
    return m;
  }
};

/// Embeds a Dim x Dim deformation gradient (or velocity gradient) in 3x3, with 1 (or 0) out of plane.
template <int Dim>
inline Mat3 embed(const Mat<Dim>& a, Real out_of_plane_diagonal) {
  Mat3 m = Mat3::Zero();
  m.template topLeftCorner<Dim, Dim>() = a;
  for (int i = Dim; i < 3; ++i) m(i, i) = out_of_plane_diagonal;
  return m;
}

}  // namespace mpm
