#pragma once
// Helpers for tests that build simulations from YAML text.
#include <map>
#include <memory>
#include <string>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/scene/scene_loader.hpp"

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

/// Total linear momentum of all bodies.
template <int Dim>
Vec<Dim> total_momentum(const Simulation<Dim>& sim) {
  Vec<Dim> p = Vec<Dim>::Zero();
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i) p += b.particles.mass[i] * Vec<Dim>(b.particles.v[i]);
  return p;
}

/// Angular momentum about the origin, sum m_p x_p x v_p (2D: the z component).
inline Real angular_momentum(const Simulation<2>& sim) {
  Real L = 0;
  for (const auto& b : sim.bodies())
    for (Index i = 0; i < b.particles.size(); ++i)
      L +=
          b.particles.mass[i] * (b.particles.x[i][0] * b.particles.v[i][1] - b.particles.x[i][1] * b.particles.v[i][0]);
  return L;
}

}  // namespace mpm::test
