#pragma once
// Helpers for tests that build simulations from YAML text.
#include <memory>
#include <string>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/scene_loader.hpp"

namespace mpm::test {

template <int Dim>
std::unique_ptr<Simulation<Dim>> simulation_from_yaml(const std::string& yaml, const std::string& name = "test.yaml") {
  app::register_modules();  // optional modules' materials (plasticity), before the scene is parsed
  return app::build_simulation<Dim>(parse_scene(yaml, name));
}

}  // namespace mpm::test
