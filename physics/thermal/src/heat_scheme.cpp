// `solver.scheme: heat`, the thermal analysis (heat_only_scheme.hpp): its declaration in the scheme registry, its
// makers per dimension and shape function, and the check that refuses what a still body cannot honour.
#include "heat_scheme.hpp"

#include <fmt/format.h>

#include <string>

#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "mpm/shape/shape_functions.hpp"
#include "mpm/thermal/heat_only_scheme.hpp"
#include "mpm/thermal/thermal_description.hpp"

namespace mpm::thermal {
namespace {

template <int Dim>
std::unique_ptr<Scheme<Dim>> make_heat_only(const SceneDescription& scene) {
  std::unique_ptr<Scheme<Dim>> scheme;
  dispatch_shape(scene.solver.shape_function, [&]<class Shape>() {
    if constexpr (shape_exists_in<Shape, Dim>) {
      if constexpr (Dim == 2 && shape_axisymmetric<Shape>)
        if (scene.grid.coordinates == Coordinates::axisymmetric) {
          scheme = std::make_unique<HeatOnlyScheme<Dim, Shape, AxisymmetricCoordinates>>();
          return;
        }
      scheme = std::make_unique<HeatOnlyScheme<Dim, Shape>>();
    }
  });
  return scheme;
}

/// The schemes that run the coupled analysis, for the refusals: those with an explicit momentum update (their traits
/// take local damping), named by the registry.
std::string coupled_schemes() {
  return scheme_names_where([](const SchemeTraits& t) { return t.local_damping.yes; });
}

/// The scene keys a heat analysis cannot honour, refused where they are given: it needs the `thermal:` section,
/// and its bodies neither move nor strain, so a thermal expansion or a gravity would be silently ignored.
void check_heat_scene(const io::YamlReader& reader, const io::YamlMap& top, const SceneDescription& scene) {
  const io::YamlMap solver = reader.map(top.required("solver"));
  if (!top.find(section_key))
    reader.fail(solver.required("scheme"),
                "scheme: heat is a thermal analysis (heat conduction alone) and needs a thermal: section");
  for (const auto& [name, md] : scene.materials)
    if (const auto it = md.parameters.find("thermal_expansion"); it != md.parameters.end() && it->second != 0)
      throw SceneError(md.where, "materials." + name + ".thermal_expansion",
                       fmt::format("scheme: heat keeps the bodies still, so the thermal expansion of material '{}' "
                                   "would be ignored: remove it, or take an explicit scheme ({}) for the coupled "
                                   "analysis",
                                   name, coupled_schemes()));
  if (const auto gravity = solver.find("gravity"))
    for (double g : scene.solver.gravity)
      if (g != 0)
        reader.fail(*gravity, fmt::format("scheme: heat keeps the bodies still, so gravity would be ignored: remove "
                                          "it, or take an explicit scheme ({}) for the coupled analysis",
                                          coupled_schemes()));
}

}  // namespace

void register_heat_scheme() {
  const char* const still = "scheme: heat keeps the bodies still (a thermal analysis)";
  register_scheme(
      {.name = "heat",
       .description = "Heat conduction alone (module `thermal`, Alg. 8): the bodies stay still and the step is the "
                      "diffusion bound, not the CFL bound; needs `thermal:`, takes contact's `thermal_conductance`, "
                      "refuses `thermal_expansion`, `gravity`, `damping` and the affine transfers "
                      "(physics/thermal/README.md, Thermal time scales)",
       .check = &check_heat_scene,
       .make_1d = &make_heat_only<1>,
       .make_2d = &make_heat_only<2>,
       .make_3d = &make_heat_only<3>,
       .traits = {.affine_transfers = Support::no(fmt::format("{}: it transfers no velocities", still)),
                  .contact = Support{},  // for a finite contact conductance (TC.1-TC.2); nothing touches anew
                  .local_damping = Support::no(fmt::format("{}: there is no motion to damp", still)),
                  .runs_distributed = true,
                  .scatters_per_step = 3}});
}

}  // namespace mpm::thermal
