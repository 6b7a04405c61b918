#pragma once
// Helpers of the implicit scheme's tests: the scheme's solver record, momenta (scenes from YAML text with
// @KEY@ placeholders: scene_fixture.hpp).
#include <string>

#include "../libmpm/scene_fixture.hpp"
#include "mpm/implicit/implicit_scheme.hpp"

namespace mpm::test {

template <int Dim>
const implicit::StepRecord& solver_record(const Simulation<Dim>& sim) {
  return dynamic_cast<const implicit::ImplicitScheme<Dim>&>(sim.scheme()).last_step();
}

template <int Dim>
Vec<Dim> linear_momentum(const Simulation<Dim>& sim) {
  Vec<Dim> p = Vec<Dim>::Zero();
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) p += b.particles.mass[i] * Vec<Dim>(b.particles.v[i]);
  return p;
}

/// sum m x x v about the origin (2D: the z component).
inline Real angular_momentum_z(const Simulation<2>& sim) {
  Real L = 0;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i)
      L +=
          b.particles.mass[i] * (b.particles.x[i][0] * b.particles.v[i][1] - b.particles.x[i][1] * b.particles.v[i][0]);
  return L;
}

}  // namespace mpm::test
