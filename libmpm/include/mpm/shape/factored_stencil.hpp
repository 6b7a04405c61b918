#pragma once
/// \file factored_stencil.hpp
/// A tensor-product stencil kept in factored form: the flat index of its first node and the 1D weights
/// and derivatives per axis. phi_I = prod_d N_d and grad phi_I (review eq. 3.17) are formed when a node
/// is visited. TLMPM caches one per particle for the whole run (the reference positions never move):
/// with hats in 3D that is 104 B per particle instead of the 368 B of a full Stencil, and each of the
/// three TLMPM particle passes reads it, so a cache that fits the processor's caches matters more than
/// the 5 multiplications per node it costs to rebuild w and grad (bench_taylor: see bench/README.md).
///
/// for_each_node(stencil, geometry, f) calls f(node, w, grad) for either kind, so that a scheme written
/// against it accepts both.

#include <type_traits>
#include <utility>

#include "mpm/shape/stencil.hpp"

namespace mpm {

/// Shape functions built as products of 1D functions (every one except CPDI, whose weights come from
/// the corners of a deformed domain).
template <class Shape>
concept TensorProductShape = !requires {
  Shape::corner_domain;
};

template <int Dim, class Shape>
struct FactoredStencil {
  static constexpr int per_axis = Shape::support;

  Index base = 0;          ///< flat index of the first node (lowest index on every axis)
  Real w[Dim][per_axis];   ///< 1D weights per axis
  Real dw[Dim][per_axis];  ///< 1D derivatives per axis, 1/m

  /// The same evaluation as Stencil::compute, without forming the products.
  inline void compute(const VecU<Dim>& x, const GridGeometry<Dim>& g, const Vec<Dim>& half = Vec<Dim>::Zero()) {
    base = 0;
    for (int d = 0; d < Dim; ++d) {
      const Real xi = (x[d] - g.origin[d]) * g.inv_h[d];
      int b = 0;
      evaluate_axis<Shape>(xi, g.nodes[d], half[d] * g.inv_h[d], b, w[d], dw[d]);
      for (int k = 0; k < per_axis; ++k) dw[d][k] *= g.inv_h[d];
      base += b * g.stride[d];
    }
  }

  /// Calls f(node, phi, grad phi) for every node of the support, x fastest (the order of Stencil).
  template <class F>
  inline void for_each(const GridGeometry<Dim>& g, F&& f) const {
    if constexpr (Dim == 1) {
      for (int i = 0; i < per_axis; ++i) f(base + i, w[0][i], Vec<1>(dw[0][i]));
    } else if constexpr (Dim == 2) {
      for (int j = 0; j < per_axis; ++j)
        for (int i = 0; i < per_axis; ++i)
          f(base + i + g.stride[1] * j, w[0][i] * w[1][j], Vec<2>(dw[0][i] * w[1][j], w[0][i] * dw[1][j]));
    } else {
      for (int k = 0; k < per_axis; ++k)
        for (int j = 0; j < per_axis; ++j) {
          const Index row = base + g.stride[1] * j + g.stride[2] * k;
          const Real wjk = w[1][j] * w[2][k], djk = dw[1][j] * w[2][k], wdk = w[1][j] * dw[2][k];
          for (int i = 0; i < per_axis; ++i)
            f(row + i, w[0][i] * wjk, Vec<3>(dw[0][i] * wjk, w[0][i] * djk, w[0][i] * wdk));
        }
    }
  }
};

/// f(node, phi, grad phi) for every node of a full (precomputed) stencil.
template <int Dim, class Stored, class F>
inline void for_each_node(const Stored& st, const GridGeometry<Dim>&, F&& f) {
  for (int a = 0; a < Stored::count; ++a) {
    Vec<Dim> grad;
    for (int d = 0; d < Dim; ++d) grad[d] = st.grad[a][d];
    f(st.node[a], st.w[a], grad);
  }
}
/// f(node, phi, grad phi) for every node of a factored stencil.
template <int Dim, class Shape, class F>
inline void for_each_node(const FactoredStencil<Dim, Shape>& st, const GridGeometry<Dim>& g, F&& f) {
  st.for_each(g, std::forward<F>(f));
}

/// The stencil TLMPM caches per particle: factored for tensor-product functions, full for CPDI.
template <int Dim, class Shape>
using ReferenceStencil =
    std::conditional_t<TensorProductShape<Shape>, FactoredStencil<Dim, Shape>, Stencil<Dim, Shape>>;

}  // namespace mpm
