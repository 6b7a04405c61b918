#include "mpm/app/body_summary.hpp"

#include <fmt/format.h>

#include "mpm/core/exact_sum.hpp"

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

template std::string body_summary<1>(const Simulation<1>&);
template std::string body_summary<2>(const Simulation<2>&);
template std::string body_summary<3>(const Simulation<3>&);

}  // namespace mpm::app
