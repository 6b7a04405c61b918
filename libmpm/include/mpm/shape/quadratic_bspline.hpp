#pragma once
/// \file quadratic_bspline.hpp
/// Quadratic B-spline on the hat grid (n cells, n+1 nodes per axis), with boundary-modified functions
/// for the node on each face and the node next to it. The review gives the quadratic B-spline only as
/// a density kernel (eq. 5.10) and no boundary types; these are designed like its cubic (eqs 3.18-3.21).
///
/// Interior (type 3), r = (x - x_I)/h, the uniform quadratic B-spline centred on the node:
///   B(r) = 3/4 - r^2 for |r| <= 1/2,  (3/2 - |r|)^2 / 2 for 1/2 <= |r| <= 3/2,  0 beyond.
/// Lower face; the upper face is the mirror image (r -> -r), as types 4/2 of the cubic:
///   type 1, face node (x_I on the face; only r >= 0 lies in the box):
///     S1(r) = 1 - r for 0 <= r <= 1/2,  (3/2 - r)^2 / 2 for 1/2 <= r <= 3/2,  0 beyond;
///   type 2, the node one cell inside the face:
///     S2(r) = 1 + r for -1 <= r <= -1/2,  B(r) for r >= -1/2.
/// So in the half cell next to a face the functions are exactly the hats (1 - r, r); elsewhere they are B.
///
/// Derivation. (a) Open knots at the cell centres, {0,0,0, 1/2, 3/2, ..., n-1/2, n,n,n} (Cox-de Boor,
/// eqs 3.15-3.16, k = 2), give n+3 functions N_0..N_{n+2}. Their Greville abscissae (the coefficients
/// that reproduce x) are 0, 1/4, 1, 2, ..., n-1, n-1/4, n: all nodes except the second and the
/// second-to-last function, which sits a quarter cell inside each face. Splitting that function between
/// its two neighbouring nodes in the linear-interpolation ratio (3/4 : 1/4) merges n+3 into n+1:
///   phi_0 = N_0 + 3/4 N_1,  phi_1 = 1/4 N_1 + N_2,  phi_I = N_{I+1} (2 <= I <= n-2),
///   phi_{n-1} = N_n + 1/4 N_{n+1},  phi_n = 3/4 N_{n+1} + N_{n+2}   (for n = 2, phi_1 gets both quarters).
/// (b) Equivalently, the ghost node at -h (the only one whose B reaches into the box) is folded onto the
/// face node and its neighbour by linear extrapolation, f(-h) = 2 f(0) - f(h): S1 = B(r) + 2 B(r+1) and
/// S2 = B(r) - B(r+2) — exactly how the review's cubic types 1 and 2 arise from the uniform cubic.
/// Both forms give the formulas above (checked numerically in tests/libmpm/test_shape_functions_more.cpp).
///
/// Properties in [origin, upper]: partition of unity, linear reproduction (sum phi_I x_I = x and
/// sum x_I dphi_I = 1, as the ghost folding is exact for linear fields), non-negativity, C1 everywhere
/// (including at the face-side knots at h/2 from each face), and the face node IS interpolatory: at
/// the face phi = 1 there and 0 for every other node, so face boundary conditions act as with hats.
/// Support: 3 nodes per axis (nodes round(xi)-1 .. round(xi)+1, base clamped to the grid). A particle
/// in cell c reaches nodes c-1..c+2, hence slab_cells = 3. Two cells per axis suffice (then the middle
/// node is type 2 towards both faces).

#include <algorithm>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm {

struct QuadraticBSpline {
  static constexpr const char* name = "quadratic_bspline";
  static constexpr int support = 3;
  static constexpr int slab_cells = 3;  // a particle in cell c reaches nodes c-1..c+2
  /// Nodes a slab [sT, (s+1)T) of cells reaches on its axis: [sT - below, (s+1)T - 1 + above] (halo of a
  /// distributed run, tile_halo.hpp; test ShapeFunctionProperties.SlabThickness).
  static constexpr int slab_reach_below = 1, slab_reach_above = 2;
  static constexpr int min_cells = 2;
  static constexpr bool axisymmetric = true;  ///< usable as it is on an axisymmetric grid (review Remark 42)
  /// sum phi_I ((x_I - x_p)/h)^2 of a particle whose nodes are all of the uniform type (the B-spline's variance);
  /// smaller in the cells next to a face (APIC's filter of light nodes, transfer_kernels.hpp).
  static constexpr Real interior_second_moment = Real(0.25);

  /// Type 3, the uniform quadratic B-spline B(r).
  static inline void interior(Real r, Real& w, Real& dw) {
    const Real a = std::abs(r), s = r < 0 ? -1 : 1;
    if (a <= Real(0.5)) {
      w = Real(0.75) - r * r;
      dw = -2 * r;
    } else if (a <= Real(1.5)) {
      const Real b = Real(1.5) - a;
      w = b * b / 2;
      dw = -s * b;
    } else {
      w = dw = 0;
    }
  }
  /// Type 1, the node on the lower face, for r >= 0 (the side in the box). The upper face node is its
  /// mirror image; mirroring (rather than |r|) gives the in-box slope at r = 0, where the kink is.
  static inline void face_lower(Real r, Real& w, Real& dw) {
    if (r <= Real(0.5)) {
      w = 1 - r;
      dw = -1;
    } else {
      interior(r, w, dw);
    }
  }

  static inline void evaluate(Real xi, int nodes, int& base, Real* w, Real* dw) {
    const int last = nodes - 1;
    base = std::clamp(static_cast<int>(std::floor(xi + Real(0.5))) - 1, 0, nodes - 3);
    for (int k = 0; k < support; ++k) {
      const int node = base + k;
      const Real r = xi - node;
      if (node == 0) {
        face_lower(r, w[k], dw[k]);
      } else if (node == last) {
        face_lower(-r, w[k], dw[k]);
        dw[k] = -dw[k];
      } else if (node == 1 && r <= Real(-0.5)) {  // type 2, in the half cell next to the lower face
        w[k] = 1 + r;
        dw[k] = 1;
      } else if (node == last - 1 && r >= Real(0.5)) {  // mirrored type 2, next to the upper face
        w[k] = 1 - r;
        dw[k] = -1;
      } else {
        interior(r, w[k], dw[k]);
      }
    }
  }
};

}  // namespace mpm
