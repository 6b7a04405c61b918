#pragma once
/// \file thermal_description.hpp
/// The `thermal:` section of a scene (docs/scene-reference.md), as plain data: what the section parser
/// (thermal_section.cpp) checked and the builder (build_heat_conduction.hpp) turns into the module.
/// Temperatures in K, heat flux in W/m^2, sources in W/m^3; expressions are muparser text.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mpm/scene/scene.hpp"

namespace mpm::thermal {

/// Thermal condition on one face of the grid box: nodes held at a temperature, or a prescribed heat flux
/// q* = q.n (outward normal; positive = heat leaving the body), the boundary term of eq. 5.21.
struct ThermalFace {
  std::optional<std::string> temperature;  ///< K, expression of t
  std::optional<std::string> flux;         ///< W/m^2, expression of t
  SourceLocation where;
};

/// Particles whose temperature is held (the Dirichlet condition on particles of review §5.3.3 / Tao et al.
/// 2016): those inside the box [min, max] at the start.
struct FixedTemperatureRegion {
  std::array<double, 3> min{0, 0, 0}, max{0, 0, 0};  ///< m
  std::string temperature;                           ///< K, expression of t
  SourceLocation where;
};

struct ThermalDescription {
  /// K, expression of x, y, z; empty: each material's room_temperature.
  std::optional<std::string> initial_temperature;
  std::string source = "0";  ///< gamma* of eq. 5.18, W/m^3, expression of x, y, z, t
  /// Faces x_min, x_max, y_min, y_max, z_min, z_max; no condition = insulated (zero flux).
  std::array<ThermalFace, 6> boundary;
  std::vector<FixedTemperatureRegion> fixed_temperature;
  /// The particles' relaxation time towards the grid field in cell diffusion times (eq. TP.1); 0: none.
  double particle_relaxation = 0.5;
  int projection_iterations = 1;  ///< Richardson steps of the relaxation target (eq. TP.2)
  SourceLocation where;
};

/// Key of the section in the scene and in SceneDescription::extensions.
inline constexpr const char* section_key = "thermal";

}  // namespace mpm::thermal
