#include "mpm/thermal/register.hpp"

#include <mutex>

#include "heat_scheme.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_extension.hpp"
#include "mpm/thermal/output_fields.hpp"
#include "thermal_section.hpp"

namespace mpm::thermal {

template <int Dim>
std::shared_ptr<Module<Dim>> build_heat_conduction(const SceneDescription&, std::vector<Body<Dim>>&,
                                                   const GridGeometry<Dim>&);

namespace {

using io::Range;

/// The keys this module adds to every material model (docs/scene-reference.md, thermal).
std::vector<ParameterSpec> thermal_parameters() {
  const char* const with_section = "required with `thermal:`";
  std::vector<ParameterSpec> parameters = {
      ParameterSpec::optional("thermal_conductivity", "W/(m K)", Range::at_least(0), with_section,
                              "isotropic thermal conductivity k (eq. 5.19)"),
      ParameterSpec::optional("specific_heat", "J/(kg K)", Range::above(0), with_section, "specific heat c (eq. 5.18)"),
      ParameterSpec::optional("thermal_expansion", "1/K", Range::any(), "absent: no expansion",
                              "linear thermal expansion coefficient alpha (eq. 5.26); linear_elastic, johnson_cook "
                              "and j2_plasticity only"),
  };
  for (const char* component : {"xx", "yy", "zz", "xy", "yz", "xz"})
    parameters.push_back(ParameterSpec::optional(
        std::string("thermal_conductivity_") + component, "W/(m K)", Range::any(), "0 (with the other components)",
        std::string("component ") + component +
            " of an anisotropic conductivity tensor, instead of thermal_conductivity (symmetric positive "
            "semi-definite)"));
  parameters.push_back(ParameterSpec::with_default("room_temperature", "K", 293.15, Range::above(0),
                                                   "initial temperature and reference of the thermal energy"));
  return parameters;
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_common_material_parameters(thermal_parameters());
    // prepared before the first snapshot: conduction adds particle fields (temperature, heat flux)
    register_scene_extension({.key = "thermal",
                              .parse = &parse_thermal_section,
                              .prepare_1d = &build_heat_conduction<1>,
                              .prepare_2d = &build_heat_conduction<2>,
                              .prepare_3d = &build_heat_conduction<3>,
                              .keys = thermal_keys(),
                              .description = "[Heat conduction](#thermal) (module `thermal`): its presence turns "
                                             "conduction on"});
    register_output_fields();
    register_heat_scheme();
  });
}

}  // namespace mpm::thermal
