#include "mpm/app/body_summary.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/core/exact_sum.hpp"
#include "mpm/geometry/mass_properties.hpp"
#include "mpm/sets/particle_sets.hpp"

namespace mpm::app {

template <int Dim>
std::string body_summary(const Simulation<Dim>& sim) {
  const bool revolved = sim.grid().geometry.coordinates == Coordinates::axisymmetric;
  const int volume_power = revolved ? 3 : Dim;
  const char* mass_unit = revolved || Dim == 3 ? "kg" : Dim == 2 ? "kg/m" : "kg/m^2";
  std::string text;
  for (const auto& b : sim.bodies()) {
    ExactSum volume, mass;
    for (Index i = 0; i < b.particles.size(); ++i) {
      volume.add(b.particles.volume0[i]);
      mass.add(b.particles.mass[i]);
    }
    text +=
        fmt::format("  body '{}': {} particle{}, volume {:.10g} m^{}, mass {:.10g} {}\n", b.name, b.particles.size(),
                    b.particles.size() == 1 ? "" : "s", volume.value(), volume_power, mass.value(), mass_unit);
  }
  return text;
}

template <int Dim>
std::string set_summary(const Simulation<Dim>& sim, const SceneDescription& scene) {
  const bool revolved = sim.grid().geometry.coordinates == Coordinates::axisymmetric;
  const char* mass_unit = revolved || Dim == 3 ? "kg" : Dim == 2 ? "kg/m" : "kg/m^2";
  std::string text;
  for (std::size_t k = 0; k < scene.sets.size(); ++k) {
    const std::uint32_t bit = set_bit(static_cast<int>(k));
    Index count = 0;
    ExactSum mass;
    std::vector<std::string> bodies;
    for (const auto& b : sim.bodies()) {
      if (!b.particles.has_field(keys::particle_sets)) continue;
      const auto& bits = b.particles.field(keys::particle_sets);
      const Index before = count;
      for (Index i = 0; i < b.particles.size(); ++i)
        if (bits[static_cast<std::size_t>(i)] & bit) {
          ++count;
          mass.add(b.particles.mass[i]);
        }
      if (count > before) bodies.push_back(b.name);
    }
    const std::string& name = scene.sets[k].name;
    if (count == 0) {
      text += fmt::format("  set '{}': no particle (its bodies, region and ids select none)\n", name);
      continue;
    }
    text += fmt::format("  set '{}': {} particle{} in {}, mass {:.10g} {}\n", name, count, count == 1 ? "" : "s",
                        fmt::join(bodies, ", "), mass.value(), mass_unit);
  }
  return text;
}

template <int Dim>
std::string body_certificates(const Simulation<Dim>& sim, const SceneDescription& scene) {
  std::string text;
  if constexpr (Dim == 3) {
    for (const auto& b : sim.bodies()) {
      const auto description = std::find_if(scene.bodies.begin(), scene.bodies.end(),
                                            [&](const BodyDescription& d) { return d.name == b.name; });
      if (description == scene.bodies.end() || !shape_kind(description->shape).traits.exact_volume) continue;
      const auto source = geometry::exact_properties(*make_shape_region<3>(description->shape));
      if (!source) continue;
      std::vector<Vec<3>> positions;
      std::vector<Real> volumes;
      positions.reserve(static_cast<std::size_t>(b.particles.size()));
      volumes.reserve(static_cast<std::size_t>(b.particles.size()));
      for (Index i = 0; i < b.particles.size(); ++i) {
        positions.emplace_back(b.particles.x[i]);
        volumes.push_back(b.particles.volume0[i]);
      }
      text += fmt::format("  body '{}':\n", b.name) +
              geometry::format_certificate(
                  geometry::certify(source->exact, geometry::particle_properties(positions, volumes), source->source),
                  "    ");
    }
  }
  return text;
}

template std::string body_summary<1>(const Simulation<1>&);
template std::string body_summary<2>(const Simulation<2>&);
template std::string body_summary<3>(const Simulation<3>&);

template std::string set_summary<1>(const Simulation<1>&, const SceneDescription&);
template std::string set_summary<2>(const Simulation<2>&, const SceneDescription&);
template std::string set_summary<3>(const Simulation<3>&, const SceneDescription&);
template std::string body_certificates<1>(const Simulation<1>&, const SceneDescription&);
template std::string body_certificates<2>(const Simulation<2>&, const SceneDescription&);
template std::string body_certificates<3>(const Simulation<3>&, const SceneDescription&);

}  // namespace mpm::app
