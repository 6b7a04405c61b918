#include "mpm/thermal/register.hpp"

#include <limits>
#include <mutex>

#include "mpm/material_catalog.hpp"
#include "mpm/scene_extension.hpp"
#include "mpm/thermal/output_fields.hpp"
#include "thermal_section.hpp"

namespace mpm::thermal {

template <int Dim>
std::shared_ptr<Module<Dim>> build_heat_conduction(const SceneDescription&, std::vector<Body<Dim>>&,
                                                   const GridGeometry<Dim>&);

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

ParameterSpec optional(std::string name, std::string unit, std::string description, double lower = -inf,
                       bool lower_inclusive = true) {
  ParameterSpec p{
      std::move(name), std::move(unit), std::move(description), std::nullopt, lower, lower_inclusive, inf, true};
  p.optional = true;
  return p;
}

std::vector<ParameterSpec> thermal_parameters() {
  std::vector<ParameterSpec> p = {
      optional("thermal_conductivity", "W/(m K)", "isotropic thermal conductivity k (eq. 5.19)", 0.0, true),
      optional("specific_heat", "J/(kg K)", "specific heat c (eq. 5.18)", 0.0, false),
      optional("thermal_expansion", "1/K", "linear thermal expansion coefficient alpha (eq. 5.26)"),
  };
  for (const char* c : {"xx", "yy", "zz", "xy", "yz", "xz"})
    p.push_back(optional(std::string("thermal_conductivity_") + c, "W/(m K)",
                         std::string("component ") + c +
                             " of an anisotropic conductivity tensor (instead of "
                             "thermal_conductivity)"));
  ParameterSpec room{"room_temperature",
                     "K",
                     "initial temperature and reference of the thermal energy",
                     293.15,
                     0.0,
                     false,
                     inf,
                     true};
  p.push_back(room);
  return p;
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_common_material_parameters(thermal_parameters());
    // prepared before the first snapshot: conduction adds particle fields (temperature, heat flux)
    SceneExtension e;
    e.key = "thermal";
    e.parse = &parse_thermal_section;
    e.prepare_1d = &build_heat_conduction<1>;
    e.prepare_2d = &build_heat_conduction<2>;
    e.prepare_3d = &build_heat_conduction<3>;
    register_scene_extension(e);
    register_output_fields();
  });
}

}  // namespace mpm::thermal
