#pragma once
/// \file cpdi.hpp
/// Convected particle domain interpolation (review §3.6, Alg. 5): CPDI-L2 (1D), CPDI-R4 and CPDI-Q4
/// (2D quadrilaterals), CPDI-T3 (2D triangles) and CPDI-Tet4 (3D tetrahedra). The weights of a particle
/// are those of its element's corners (cpdi_elements.hpp) spread on the grid with hat functions.
///
/// Domain update, chosen per scene (field present = mode):
/// - with F (original CPDI, eq. 3.27): corners x_c = x_p + F_p (X_c - X_p), from the reference offsets in
///   the field "cpdi_corner_offsets0"; the domain stays a parallelogram / affine image (R4, L2);
/// - with the corners (CPDI2, eq. 3.38): the field "cpdi_corners" holds x_c, moved every step with the
///   grid velocity, x_c += dt sum_I N_I(x_c) v_I (cpdi_corner_tracking.hpp); no gaps between particles.
///
/// The stencil is a dense block of 4 nodes per axis around the particle's cell (nodes c-1..c+2), as for
/// GIMP: every corner must lie within one cell of the particle's cell, so a domain may grow to about two
/// cells before corners are clamped into the block (review §3.7: larger domains open "holes" anyway).
/// Clamped corners keep partition of unity; corners outside the grid box are moved onto it.

#include <algorithm>
#include <cmath>

#include "mpm/particles/field_keys.hpp"
#include "mpm/shape/cpdi_elements.hpp"
#include "mpm/shape/stencil.hpp"

namespace mpm {

/// Resolves the corners of every particle once per kernel: tracked corners, or x_p + F_p offsets.
template <int Dim>
struct CpdiDomain {
  const CornerSet<Dim>* tracked = nullptr;
  const CornerSet<Dim>* offsets0 = nullptr;
  const VecU<Dim>* x;
  const MatU<Dim>* F;
  explicit CpdiDomain(const ParticleSet<Dim>& p) : x(p.x.data()), F(p.F.data()) {
    if (p.has_field(keys::cpdi_corners<Dim>))
      tracked = p.field(keys::cpdi_corners<Dim>).data();
    else
      offsets0 = p.field(keys::cpdi_corner_offsets0<Dim>).data();
  }
  CornerSet<Dim> operator()(Index i) const {
    if (tracked) return tracked[i];
    CornerSet<Dim> c;
    const Mat<Dim> Fi = F[i];
    for (int k = 0; k < 4; ++k) c[k] = x[i] + Fi * Vec<Dim>(offsets0[i][k]);
    return c;
  }
};

/// A CPDI shape function on `Element`; `FollowsF`: the scene's default domain update; `TracksCorners`: the corners
/// may move on their own (`solver.cpdi_domain_update: corners`), false for CPDI-R4, whose domain stays the
/// parallelogram F maps the initial one to (eq. 3.27).
template <class Element, bool FollowsF, int Reach, bool TracksCorners = true>
struct Cpdi {
  using element = Element;
  static constexpr int dimension = Element::dimension;
  static constexpr int reach = Reach;
  static constexpr int support = 2 * Reach + 2;
  static constexpr int slab_cells = 2 * support - 3;  // 5 for reach 1 (the GIMP block); typed shape tests
  // corners' hats (tile_halo.hpp); below: 2 Reach, a short last slab at the upper face reaches that far (test)
  static constexpr int slab_reach_below = 2 * Reach, slab_reach_above = Reach + 1;
  static constexpr int min_cells = support - 1;
  static constexpr bool corner_domain = true;
  static constexpr bool follows_F_by_default = FollowsF;
  static constexpr bool tracks_corners = TracksCorners;
  template <int Dim>
  using Domain = CpdiDomain<Dim>;
};

struct CpdiL2 : Cpdi<CpdiSegment, true, 1> {
  static constexpr const char* name = "cpdi_l2";
};
struct CpdiR4 : Cpdi<CpdiQuad, true, 2, false> {
  static constexpr const char* name = "cpdi_r4";
};
struct CpdiQ4 : Cpdi<CpdiQuad, false, 2> {
  static constexpr const char* name = "cpdi_q4";
};
struct CpdiT3 : Cpdi<CpdiTriangle, false, 2> {
  static constexpr const char* name = "cpdi_t3";
};
struct CpdiTet4 : Cpdi<CpdiTetrahedron, false, 1> {
  static constexpr const char* name = "cpdi_tet4";
};

template <int Dim, class Shape>
requires Shape::corner_domain struct ParticleDomain<Dim, Shape> : CpdiDomain<Dim> {
  using CpdiDomain<Dim>::CpdiDomain;
};

/// The CPDI stencil (Alg. 5): the same dense 4^Dim block layout as the tensor-product stencils, so every
/// scheme, the slab colouring and APIC use it unchanged; the weights are accumulated corner by corner.
template <int Dim, class Shape>
requires Shape::corner_domain struct Stencil<Dim, Shape> {
  static constexpr int reach = Shape::reach;  ///< cells a corner may lie beyond the particle's cell
  static constexpr int per_axis = 2 * reach + 2;
  static constexpr int count = Dim == 1 ? per_axis : (Dim == 2 ? per_axis * per_axis : per_axis * per_axis * per_axis);
  using Element = typename Shape::element;
  static_assert(Element::dimension == Dim, "a CPDI element is defined for one dimension only");

  Index node[count];
  Real w[count];
  Real grad[count][Dim];       ///< 1/m
  Real offset[Dim][per_axis];  ///< x_I - x_p per axis (m), for APIC

  Vec<Dim> node_offset(int a) const {
    Vec<Dim> r;
    for (int d = 0; d < Dim; ++d) {
      r[d] = offset[d][a % per_axis];
      a /= per_axis;
    }
    return r;
  }

  inline void compute(const VecU<Dim>& x, const GridGeometry<Dim>& g, const CornerSet<Dim>& corners) {
    int base[Dim], stride[Dim];
    for (int d = 0; d < Dim; ++d) {
      const Real xi = (x[d] - g.origin[d]) * g.inv_h[d];
      base[d] = std::clamp(static_cast<int>(std::floor(xi)) - reach, 0, g.nodes[d] - per_axis);
      for (int k = 0; k < per_axis; ++k) offset[d][k] = (base[d] + k - xi) * g.h[d];
      stride[d] = d == 0 ? 1 : stride[d - 1] * per_axis;
    }
    for (int a = 0; a < count; ++a) {
      Index n = 0;
      for (int d = 0, r = a; d < Dim; ++d, r /= per_axis) n += (base[d] + r % per_axis) * (d == 0 ? 1 : g.stride[d]);
      node[a] = n;
      w[a] = 0;
      for (int d = 0; d < Dim; ++d) grad[a][d] = 0;
    }
    Real wf[Element::corners], wg[Element::corners][Dim];
    Element::weights(corners, wf, wg);
    for (int c = 0; c < Element::corners; ++c) {
      // Hat functions of the corner's cell (eq. 3.17 with linear N): 2 nodes per axis.
      int lo[Dim];
      Real hat[Dim][2];
      for (int d = 0; d < Dim; ++d) {
        const Real xi = std::clamp<Real>((corners[c][d] - g.origin[d]) * g.inv_h[d], base[d], base[d] + per_axis - 1);
        const int cell = std::min(static_cast<int>(std::floor(xi)), base[d] + per_axis - 2);
        const Real f = xi - cell;
        lo[d] = cell - base[d];
        hat[d][0] = 1 - f;
        hat[d][1] = f;
      }
      for (int corner_node = 0; corner_node < (1 << Dim); ++corner_node) {
        int a = 0;
        Real N = 1;
        for (int d = 0; d < Dim; ++d) {
          const int bit = (corner_node >> d) & 1;
          a += (lo[d] + bit) * stride[d];
          N *= hat[d][bit];
        }
        w[a] += wf[c] * N;
        for (int d = 0; d < Dim; ++d) grad[a][d] += wg[c][d] * N;
      }
    }
  }
};

}  // namespace mpm
