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

#include "mpm/field_keys.hpp"
#include "mpm/particle_set.hpp"

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
}  // namespace gimp_detail

/// Shape functions whose weights depend on a particle domain provide `uses_domain = true`, an
/// `evaluate` taking the half-length, and a `Domain<Dim>` that resolves the particle data once per kernel.
struct GimpFunctions {
  static constexpr int support = 4;
  static constexpr int slab_cells = 5;  // nodes c-1..c+2, and c-2..c+1 next to the upper face
  static constexpr int min_cells = 3;
  static constexpr bool uses_domain = true;
  static inline void evaluate(Real xi, int nodes, Real a, int& base, Real* w, Real* dw) {
    gimp_detail::evaluate(xi, nodes, a, base, w, dw);
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
