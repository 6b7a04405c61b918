#pragma once
// Helpers for tests that build simulations from YAML text.
#include <map>
#include <memory>
#include <string>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/scene_loader.hpp"

namespace mpm::test {

/// `text` with every @KEY@ replaced by its value (scene templates of the tests).
inline std::string fill(std::string text, const std::map<std::string, std::string>& values) {
  for (const auto& [key, value] : values) {
    const std::string marker = "@" + key + "@";
    for (auto at = text.find(marker); at != std::string::npos; at = text.find(marker, at + value.size()))
      text.replace(at, marker.size(), value);
  }
  return text;
}

template <int Dim>
std::unique_ptr<Simulation<Dim>> simulation_from_yaml(const std::string& yaml, const std::string& name = "test.yaml") {
  app::register_modules();  // optional modules' materials (plasticity), before the scene is parsed
  return app::build_simulation<Dim>(parse_scene(yaml, name));
}

}  // namespace mpm::test
