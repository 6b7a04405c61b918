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

}  // namespace mpm::test
