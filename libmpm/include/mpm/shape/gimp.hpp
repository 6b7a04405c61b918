#pragma once
/// \file gimp.hpp
/// Generalized interpolation material point functions (review §3.3, Bardenhagen & Kober 2004): the hat
/// function averaged over the particle's domain, phi_I(x_p) = (1/l_p) int_{x_p - l_p/2}^{x_p + l_p/2} N_I.
/// Written through the antiderivative G of the hat (G(s) = (1+s)^2/2 on [-1, 0], 1 - (1-s)^2/2 on [0, 1],
/// 0 below, 1 above), with a = l_p/(2h) the half-length in cells and r = (x_p - x_I)/h:
///   phi(r) = [G(r + a) - G(r - a)] / (2a),   dphi/dr = [N(r + a) - N(r - a)] / (2a),
/// which is eq. 3.12-3.13 for a <= 1/2 and stays exact for longer (stretched) domains. Domains are
/// limited to a <= 1 (two cells long), so a particle reaches at most 4 nodes per axis (docs/errata.md #5).
/// - uGIMP: l_p fixed at its initial value (cell size / particles per cell).
/// - cpGIMP: l_p(t) = l_p(0) F_aa per axis (eq. 3.14): stretched, never sheared.
/// Weights keep partition of unity as long as the domain stays inside the grid box; there are no
/// ghost nodes, so a domain sticking out of the box loses the part outside.

#include <algorithm>
#include <cmath>

#include "mpm/particles/field_keys.hpp"
#include "mpm/particles/particle_set.hpp"

namespace mpm {

namespace gimp_detail {
inline Real hat(Real s) { return std::max<Real>(0, 1 - std::abs(s)); }
inline Real hat_integral(Real s) {
  if (s <= -1) return 0;
  if (s <= 0) return 0.5 * (1 + s) * (1 + s);
  if (s <= 1) return 1 - 0.5 * (1 - s) * (1 - s);
  return 1;
}
/// Weights of nodes base..base+3 for a particle at xi (cells) with half-length a (cells).
inline void evaluate(Real xi, int nodes, Real a, int& base, Real* w, Real* dw) {
  a = std::clamp<Real>(a, 1e-12, 1);
  base = std::clamp(static_cast<int>(std::floor(xi)) - 1, 0, nodes - 4);
  const Real inv = 1 / (2 * a);
  for (int k = 0; k < 4; ++k) {
    const Real r = xi - (base + k);
    w[k] = (hat_integral(r + a) - hat_integral(r - a)) * inv;
    dw[k] = (hat(r + a) - hat(r - a)) * inv;
  }
}
/// The moments of the hat over [-1, s] that the r-weighted averages need: M(s) = int N(t) t dt and
/// P(s) = int N'(t) t dt (both 0 below -1; M(1) = 0, P(1) = -1).
inline Real hat_first_moment(Real s) {
  if (s <= -1 || s >= 1) return 0;
  return s <= 0 ? s * s / 2 + s * s * s / 3 - Real(1) / 6 : s * s / 2 - s * s * s / 3 - Real(1) / 6;
}
inline Real hat_slope_moment(Real s) {
  if (s <= -1) return 0;
  if (s >= 1) return -1;
  return s <= 0 ? (s * s - 1) / 2 : -(1 + s * s) / 2;
}
/// Axisymmetric weights of nodes base..base+3 on the radial axis, the grid starting on the axis (xi = r/h):
/// the averages over the domain [xi - a, xi + a] weighted by r (Nairn & Guilkey 2015), with u = xi - xi_I,
///   w_I  = int N_I r dr / int r dr  = (xi_I [G(u + a) - G(u - a)] + M(u + a) - M(u - a)) / (2 a xi),
///   dw_I = int N_I' r dr / int r dr = (xi_I [N(u + a) - N(u - a)] + P(u + a) - P(u - a)) / (2 a xi),
/// and in w_planar the unweighted averages of `evaluate` (the hoop weight is w_planar / r).
inline void evaluate_radial(Real xi, int nodes, Real a, int& base, Real* w, Real* dw, Real* w_planar) {
  Real unused[4];
  evaluate(xi, nodes, a, base, w_planar, unused);
  a = std::clamp<Real>(a, 1e-12, 1);
  const Real inv = 1 / (2 * a * xi);
  for (int k = 0; k < 4; ++k) {
    const Real node = base + k, u = xi - node;
    w[k] =
        (node * (hat_integral(u + a) - hat_integral(u - a)) + hat_first_moment(u + a) - hat_first_moment(u - a)) * inv;
    dw[k] = (node * (hat(u + a) - hat(u - a)) + hat_slope_moment(u + a) - hat_slope_moment(u - a)) * inv;
  }
}
}  // namespace gimp_detail

/// Shape functions whose weights depend on a particle domain provide `uses_domain = true`, an
/// `evaluate` taking the half-length, and a `Domain<Dim>` that resolves the particle data once per kernel.
struct GimpFunctions {
  static constexpr int support = 4;
  static constexpr int slab_cells = 5;  // nodes c-1..c+2, and c-2..c+1 next to the upper face
  /// Nodes a slab [sT, (s+1)T) of cells reaches on its axis: [sT - below, (s+1)T - 1 + above] (halo of a
  /// distributed run, tile_halo.hpp; test ShapeFunctionProperties.SlabThickness).
  static constexpr int slab_reach_below = 2, slab_reach_above = 2;
  static constexpr int min_cells = 3;
  static constexpr bool uses_domain = true;
  static inline void evaluate(Real xi, int nodes, Real a, int& base, Real* w, Real* dw) {
    gimp_detail::evaluate(xi, nodes, a, base, w, dw);
  }
  /// The radial axis of an axisymmetric grid (axisymmetric.hpp): r-weighted averages, and the plain ones.
  static inline void evaluate_radial(Real xi, int nodes, Real a, int& base, Real* w, Real* dw, Real* w_planar) {
    gimp_detail::evaluate_radial(xi, nodes, a, base, w, dw, w_planar);
  }
};

struct UGimp : GimpFunctions {
  static constexpr const char* name = "gimp";
  /// Half-lengths l_p(0)/2 (m) from the field keys::domain_half_length0.
  template <int Dim>
  struct Domain {
    const VecU<Dim>* half0;
    explicit Domain(const ParticleSet<Dim>& p) : half0(p.field(keys::domain_half_length0<Dim>).data()) {}
    Vec<Dim> operator()(Index i) const { return half0[i]; }
  };
};

struct CpGimp : GimpFunctions {
  static constexpr const char* name = "cpgimp";
  static constexpr bool axisymmetric = true;      ///< with the r-weighted radial averages (evaluate_radial)
  static constexpr bool stretched_domain = true;  ///< the domain follows diag F (eq. 3.14): drawn so in the output
  /// Half-lengths l_p(0)/2 F_aa (m), eq. 3.14.
  template <int Dim>
  struct Domain {
    const VecU<Dim>* half0;
    const MatU<Dim>* F;
    explicit Domain(const ParticleSet<Dim>& p) : half0(p.field(keys::domain_half_length0<Dim>).data()), F(p.F.data()) {}
    Vec<Dim> operator()(Index i) const { return half0[i].cwiseProduct(Vec<Dim>(F[i].diagonal())); }
  };
};

}  // namespace mpm
