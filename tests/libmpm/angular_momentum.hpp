#pragma once
// The particles' orbital angular momentum sum m (x - c) x v about the centre c of a 2D scene (the spinning-disk
// tests of APIC and PolyPIC; the affine parts C_p carry an O(h^2) share more, not counted here).
#include "mpm/simulation/simulation.hpp"

namespace mpm::test {

inline Real orbital_angular_momentum(const Simulation<2>& sim, const Vec<2>& centre) {
  Real L = 0;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) {
      const Vec<2> r = Vec<2>(b.particles.x[i]) - centre;
      L += b.particles.mass[i] * (r[0] * b.particles.v[i][1] - r[1] * b.particles.v[i][0]);
    }
  return L;
}

}  // namespace mpm::test
