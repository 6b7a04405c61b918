#pragma once
/// \file stencil.hpp
/// Tensor-product weights phi_I(x_p) and gradients grad phi_I(x_p) of one particle on every node of its
/// support (review eq. 3.17). `Shape` supplies the 1D functions; this file is the only place that
/// combines axes, so a new shape function is one new header with an `evaluate` like LinearHat's.

#include "mpm/particles/particle_set.hpp"

namespace mpm {

/// Per-particle data a shape function needs besides the position: nothing for grid-only functions;
/// the domain half-lengths for GIMP (Shape::Domain resolves the fields once per kernel, not per particle).
template <int Dim, class Shape>
struct ParticleDomain {
  explicit ParticleDomain(const ParticleSet<Dim>&) {}
  Vec<Dim> operator()(Index) const { return Vec<Dim>::Zero(); }
};
template <int Dim, class Shape>
requires Shape::uses_domain struct ParticleDomain<Dim, Shape> : Shape::template Domain<Dim> {
  using Shape::template Domain<Dim>::Domain;
};

/// One axis of a shape function: the weights w and derivatives dw (per cell) of the `Shape::support` nodes from
/// `base`, at the normalised coordinate xi = (x - origin)/h on an axis of `nodes` nodes; `a` is the domain
/// half-length in cells, read only by domain-based functions (GIMP).
template <class Shape>
inline void evaluate_axis(Real xi, int nodes, Real a, int& base, Real* w, Real* dw) {
  if constexpr (requires { Shape::uses_domain; })
    Shape::evaluate(xi, nodes, a, base, w, dw);
  else
    Shape::evaluate(xi, nodes, base, w, dw);
}

template <int Dim, class Shape>
struct Stencil {
  static constexpr int per_axis = Shape::support;
  static constexpr int count = Dim == 1 ? per_axis : (Dim == 2 ? per_axis * per_axis : per_axis * per_axis * per_axis);

  Index node[count];
  Real w[count];
  Real grad[count][Dim];       ///< 1/m
  Real offset[Dim][per_axis];  ///< x_I - x_p per axis for the per_axis nodes of that axis, m (APIC)

  /// x_I - x_p of node a of the stencil (m).
  Vec<Dim> node_offset(int a) const {
    Vec<Dim> r;
    for (int d = 0; d < Dim; ++d) {
      r[d] = offset[d][a % per_axis];
      a /= per_axis;
    }
    return r;
  }

  /// `half` (m): the particle's domain half-lengths, read only by domain-based functions (GIMP).
  /// The 3D linear-hat stencil is always inlined: once the kernels gained their coordinate-system parameter
  /// (axisymmetry), GCC 12 stopped inlining it into the 3D linear-hat MUSL kernels, +8.3% instructions per
  /// particle-update. Forcing it everywhere costs the 2D cubic kernels +1.2% instead, so the other stencils keep
  /// the compiler's choice (bench/count_instructions.sh, PERFORMANCE.md §14).
  /// The same body twice: an attribute cannot depend on a template parameter, and moving the body into a
  /// helper changes GCC's decisions again (a forced helper: 2D linear +9.5%; a flattened wrapper: no effect).
  static constexpr bool forced_inline = Dim == 3 && per_axis == 2;
  [[gnu::always_inline]] inline void compute(const VecU<Dim>& x, const GridGeometry<Dim>& g,
                                             const Vec<Dim>& half = Vec<Dim>::Zero()) requires forced_inline {
    int base[Dim];
    Real wa[Dim][per_axis], da[Dim][per_axis];
    for (int d = 0; d < Dim; ++d) {
      const Real xi = (x[d] - g.origin[d]) * g.inv_h[d];
      evaluate_axis<Shape>(xi, g.nodes[d], half[d] * g.inv_h[d], base[d], wa[d], da[d]);
      scale_and_offset(d, xi, g, base[d], da[d]);
    }
    combine(base, wa, da, g);
  }
  inline void compute(const VecU<Dim>& x, const GridGeometry<Dim>& g,
                      const Vec<Dim>& half = Vec<Dim>::Zero()) requires(!forced_inline) {
    int base[Dim];
    Real wa[Dim][per_axis], da[Dim][per_axis];
    for (int d = 0; d < Dim; ++d) {
      const Real xi = (x[d] - g.origin[d]) * g.inv_h[d];
      evaluate_axis<Shape>(xi, g.nodes[d], half[d] * g.inv_h[d], base[d], wa[d], da[d]);
      scale_and_offset(d, xi, g, base[d], da[d]);
    }
    combine(base, wa, da, g);
  }

 protected:
  /// Derivatives of axis d from per cell to per metre; the node offsets of the axis.
  inline void scale_and_offset(int d, Real xi, const GridGeometry<Dim>& g, int base, Real* da) {
    for (int k = 0; k < per_axis; ++k) {
      da[k] *= g.inv_h[d];
      offset[d][k] = (base + k - xi) * g.h[d];
    }
  }
  /// The tensor products of the 1D weights and derivatives (review eq. 3.17), x fastest.
  inline void combine(const int base[Dim], const Real wa[Dim][per_axis], const Real da[Dim][per_axis],
                      const GridGeometry<Dim>& g) {
    if constexpr (Dim == 1) {
      for (int i = 0; i < per_axis; ++i) {
        node[i] = base[0] + i;
        w[i] = wa[0][i];
        grad[i][0] = da[0][i];
      }
    } else if constexpr (Dim == 2) {
      int n = 0;
      for (int j = 0; j < per_axis; ++j)
        for (int i = 0; i < per_axis; ++i, ++n) {
          node[n] = (base[0] + i) + g.stride[1] * (base[1] + j);
          w[n] = wa[0][i] * wa[1][j];
          grad[n][0] = da[0][i] * wa[1][j];
          grad[n][1] = wa[0][i] * da[1][j];
        }
    } else {
      int n = 0;
      for (int k = 0; k < per_axis; ++k)
        for (int j = 0; j < per_axis; ++j)
          for (int i = 0; i < per_axis; ++i, ++n) {
            node[n] = (base[0] + i) + g.stride[1] * (base[1] + j) + g.stride[2] * (base[2] + k);
            const Real wjk = wa[1][j] * wa[2][k];
            w[n] = wa[0][i] * wjk;
            grad[n][0] = da[0][i] * wjk;
            grad[n][1] = wa[0][i] * da[1][j] * wa[2][k];
            grad[n][2] = wa[0][i] * wa[1][j] * da[2][k];
          }
    }
  }
};

}  // namespace mpm
