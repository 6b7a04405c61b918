#pragma once
// Random distorted CPDI particle elements, shared by the CPDI tests and the typed shape-function tests.
#include <random>

#include "mpm/geometry/cpdi_domains.hpp"
#include "mpm/shape/cpdi.hpp"

namespace mpm::test {

/// A random element around x: the reference sub-cell element of `Shape` scaled to `size` cells, then
/// sheared and stretched by a random F with det F in about [0.5, 2] and every corner moved a little.
template <int Dim, class Shape>
CornerSet<Dim> random_domain(const GridGeometry<Dim>& g, const Vec<Dim>& x, Real size, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-1, 1);
  geometry::ParticleSeeds<Dim> seed;
  seed.positions = {Vec<Dim>::Zero()};
  seed.volume = 1;
  const auto e = geometry::cpdi_particles<Dim>(seed, Vec<Dim>(size * g.h), Shape::element::corners);
  Mat<Dim> F = Mat<Dim>::Identity();
  for (int r = 0; r < Dim; ++r)
    for (int c = 0; c < Dim; ++c) F(r, c) += 0.3 * u(rng);
  CornerSet<Dim> corners;
  corners.fill(VecU<Dim>::Zero());
  for (int k = 0; k < Shape::element::corners; ++k) {
    Vec<Dim> jiggle;
    for (int d = 0; d < Dim; ++d) jiggle[d] = 0.05 * size * g.h[d] * u(rng);
    corners[k] = x + F * Vec<Dim>(e.offsets[0][k]) + jiggle;
  }
  return corners;
}

/// True when every corner lies inside the grid box and within the stencil's reach of x's cell (cpdi.hpp):
/// the case the stencil's definition covers without clamping.
template <int Dim, class Shape>
bool within_reach(const GridGeometry<Dim>& g, const Vec<Dim>& x, const CornerSet<Dim>& c) {
  bool reachable = true;
  for (int k = 0; k < Shape::element::corners; ++k)
    for (int d = 0; d < Dim; ++d) {
      const Real xi_c = (c[k][d] - g.origin[d]) * g.inv_h[d], cell = std::floor((x[d] - g.origin[d]) * g.inv_h[d]);
      reachable = reachable && xi_c >= 0 && xi_c <= g.cells(d) && xi_c >= cell - Shape::reach &&
                  xi_c <= cell + 1 + Shape::reach;
    }
  return reachable;
}

}  // namespace mpm::test
