#pragma once
/// \file cpdi_elements.hpp
/// The particle elements of CPDI (review §3.6): a particle domain is a small finite element whose
/// corners x_c carry the grid functions, N_I(x) ~ sum_c M_c(x) N_I(x_c) over the domain (eq. 3.29), so
///   phi_Ip      = sum_c w^f_c N_I(x_c),  w^f_c = (1/V_p) int M_c dV       (eq. 3.30),
///   grad phi_Ip = sum_c w^g_c N_I(x_c),  w^g_c = (1/V_p) int grad M_c dV  (eq. 3.31),
/// with sum w^f = 1 and sum w^g = 0 (eq. 3.33). Each element below gives w^f and w^g in closed form from
/// its current corners; the tests check them against Gauss integration of M_c and grad M_c.

#include <array>
#include <cmath>

#include "mpm/grid/grid.hpp"

namespace mpm {

/// Corners of one particle domain, at most four (L2: 2, T3: 3, Q4: 4, Tet4: 4), m.
template <int Dim>
using CornerSet = std::array<VecU<Dim>, 4>;

/// Two-node segment (CPDI-L2, eq. 3.26): phi = (N(x1) + N(x2))/2, dphi = (N(x2) - N(x1))/l_p.
struct CpdiSegment {
  static constexpr int dimension = 1;
  static constexpr int corners = 2;
  static Real volume(const CornerSet<1>& c) { return c[1][0] - c[0][0]; }
  static void weights(const CornerSet<1>& c, Real* wf, Real (*wg)[1]) {
    const Real inv_l = 1 / volume(c);
    wf[0] = wf[1] = 0.5;
    wg[0][0] = -inv_l;
    wg[1][0] = inv_l;
  }
};

/// Bilinear quadrilateral, corners counter-clockwise (CPDI-Q4 / "CPDI2", eqs 3.36-3.37; a
/// parallelogram gives the original CPDI-R4 weights 1/4 and eq. 3.32). V_p by the shoelace formula.
struct CpdiQuad {
  static constexpr int dimension = 2;
  static constexpr int corners = 4;
  static Real volume(const CornerSet<2>& c) {
    Real s = 0;
    for (int k = 0; k < 4; ++k) s += c[k][0] * c[(k + 1) % 4][1] - c[(k + 1) % 4][0] * c[k][1];
    return s / 2;
  }
  static void weights(const CornerSet<2>& c, Real* wf, Real (*wg)[2]) {
    const Real x1 = c[0][0], x2 = c[1][0], x3 = c[2][0], x4 = c[3][0];
    const Real y1 = c[0][1], y2 = c[1][1], y3 = c[2][1], y4 = c[3][1];
    const Real V = volume(c);
    // a and b vanish for a parallelogram: the bilinear part of the map (eq. 3.36).
    const Real a = (x4 - x1) * (y2 - y3) - (x2 - x3) * (y4 - y1);
    const Real b = (x3 - x4) * (y1 - y2) - (x1 - x2) * (y3 - y4);
    const Real inv24 = 1 / (24 * V);
    wf[0] = (6 * V - a - b) * inv24;
    wf[1] = (6 * V - a + b) * inv24;
    wf[2] = (6 * V + a + b) * inv24;
    wf[3] = (6 * V + a - b) * inv24;
    const Real inv2 = 1 / (2 * V);
    wg[0][0] = (y2 - y4) * inv2, wg[0][1] = (x4 - x2) * inv2;
    wg[1][0] = (y3 - y1) * inv2, wg[1][1] = (x1 - x3) * inv2;
    wg[2][0] = (y4 - y2) * inv2, wg[2][1] = (x2 - x4) * inv2;
    wg[3][0] = (y1 - y3) * inv2, wg[3][1] = (x3 - x1) * inv2;
  }
};

/// Linear triangle, corners counter-clockwise (CPDI-T3, eqs 3.40-3.41).
struct CpdiTriangle {
  static constexpr int dimension = 2;
  static constexpr int corners = 3;
  static Real volume(const CornerSet<2>& c) {
    return 0.5 * ((c[1][0] - c[0][0]) * (c[2][1] - c[0][1]) - (c[2][0] - c[0][0]) * (c[1][1] - c[0][1]));
  }
  static void weights(const CornerSet<2>& c, Real* wf, Real (*wg)[2]) {
    const Real inv2 = 1 / (2 * volume(c));
    for (int k = 0; k < 3; ++k) {
      const VecU<2>& next = c[(k + 1) % 3];
      const VecU<2>& prev = c[(k + 2) % 3];
      wf[k] = Real(1) / 3;
      wg[k][0] = (next[1] - prev[1]) * inv2;  // eq. 3.41: [y2 - y3, x3 - x2] / 2V for corner 1
      wg[k][1] = (prev[0] - next[0]) * inv2;
    }
  }
};

/// Linear tetrahedron (CPDI-Tet4, eqs 3.42-3.43): w^f = 1/4 and w^g_c = grad M_c, the gradients of the
/// barycentric coordinates: rows of J^-1 with J = [x2 - x1, x3 - x1, x4 - x1] (digest §A.10.5, which
/// checks that this equals eq. 3.43 for either orientation). V_p = det J / 6, positive when the
/// corners are numbered right-handed.
struct CpdiTetrahedron {
  static constexpr int dimension = 3;
  static constexpr int corners = 4;
  static Mat3 edges(const CornerSet<3>& c) {
    Mat3 J;
    for (int k = 0; k < 3; ++k) J.col(k) = c[k + 1] - c[0];
    return J;
  }
  static Real volume(const CornerSet<3>& c) { return edges(c).determinant() / 6; }
  static void weights(const CornerSet<3>& c, Real* wf, Real (*wg)[3]) {
    const Mat3 inv = edges(c).inverse();
    for (int d = 0; d < 3; ++d) {
      wg[0][d] = -(inv(0, d) + inv(1, d) + inv(2, d));
      for (int k = 0; k < 3; ++k) wg[k + 1][d] = inv(k, d);
    }
    for (int k = 0; k < 4; ++k) wf[k] = 0.25;
  }
};

}  // namespace mpm
