// `solver.scheme: implicit` (docs/scene-reference.md, solver.implicit): the options of the Newton-Krylov solve
// and what the implicit scheme refuses, each at its key (file:line:column, exit 2).
#include "implicit_section.hpp"

#include <fmt/format.h>

#include "mpm/boundary/face_condition_kind.hpp"
#include "mpm/implicit/implicit_options.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/schemes/scheme.hpp"

namespace mpm::implicit {
namespace {

using io::Range;

void read_options(const io::YamlReader& reader, const io::YamlValue& value, ImplicitOptions& o) {
  const io::YamlMap map = reader.map(value);
  map.allow({"newton_rtol", "newton_atol", "max_newton_iterations", "linear_rtol", "max_linear_iterations",
             "gmres_restart", "mass_rtol", "volumetric", "weak_node_fraction", "newton_trace"});
  if (const auto v = map.find("newton_rtol")) o.newton_rtol = reader.number(*v, Range::open(0, 1), "");
  if (const auto v = map.find("newton_atol")) o.newton_atol = reader.number(*v, Range::at_least(0), "N");
  if (const auto v = map.find("max_newton_iterations")) o.max_newton_iterations = reader.integer(*v, 1);
  if (const auto v = map.find("linear_rtol")) o.linear_rtol = reader.number(*v, Range::open(0, 1), "");
  if (const auto v = map.find("max_linear_iterations")) o.max_linear_iterations = reader.integer(*v, 1);
  if (const auto v = map.find("gmres_restart")) o.gmres_restart = reader.integer(*v, 1);
  if (const auto v = map.find("mass_rtol")) o.mass_rtol = reader.number(*v, Range::open(0, 1), "");
  if (const auto v = map.find("volumetric")) o.volumetric = reader.choice<VolumetricMode>(*v);
  if (const auto v = map.find("weak_node_fraction")) o.weak_node_fraction = reader.number(*v, Range::closed(0, 1), "");
  if (const auto v = map.find("newton_trace")) o.newton_trace = reader.boolean(*v);
}

/// The transfer choices: (92) is the FLIP update of the grid increment, nothing else.
void refuse_transfers(const io::YamlReader& reader, const io::YamlMap& map, const SolverDescription& solver) {
  if (const auto cfl = map.find("cfl"))
    reader.fail(*cfl,
                "scheme: implicit takes a fixed time step dt (it is stable for any dt, Prop. 3.1); cfl "
                "is for the explicit schemes");
  if (!find_shape_function(solver.shape_function)->multilinear)
    reader.fail(*map.find("shape_function"),
                fmt::format("scheme: implicit uses linear hats (the Q1/P0 cells of eqs. 88c-88e), not {}",
                            solver.shape_function));
  if (const auto flip = map.find("flip_fraction"); flip && solver.flip_fraction != 1)
    reader.fail(*flip,
                "scheme: implicit needs flip_fraction 1 (eq. 92: the energy and momentum proof, Cor. 3.2, "
                "holds for the FLIP update only)");
}

/// The face conditions must combine with the implicit scheme (FaceTraits::not_implicit: walls at rest only, no
/// traction, no outflow).
void refuse_boundaries(const SceneDescription& scene) {
  const auto& names = GridDescription::face_names;
  for (int f = 0; f < 2 * scene.dimension; ++f) {
    const FaceDescription& face = scene.grid.boundary[static_cast<std::size_t>(f)];
    if (const std::string why = face_traits(face).not_implicit; !why.empty())
      throw SceneError(face.where, std::string("grid.boundary.") + names[static_cast<std::size_t>(f)], why);
  }
}

void refuse_materials(const SceneDescription& scene) {
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodyDescription& body = scene.bodies[b];
    const MaterialDescription& material = scene.materials.at(body.material);
    if (material.failure)
      throw SceneError(material.failure_where, "materials." + material.name + ".failure",
                       "scheme: implicit cannot take failure: its Newton solve and energy-consistent update (ref. "
                       "003) are written for a fixed set of particles with a smooth stress, and erosion removes "
                       "particles, failure cuts the stress to a pressure; use an explicit scheme (usl, musl or usf)");
    if (const MaterialModel* model = find_material_model(material.model); !model || !model->implicit_stress)
      throw SceneError(body.where, fmt::format("bodies[{}].material", b),
                       fmt::format("scheme: implicit needs the material model {} (the algorithmic stress of "
                                   "eqs. 81-83, 90); body '{}' has material '{}' of model {}",
                                   material_model_names_where([](const MaterialModel& m) { return m.implicit_stress; }),
                                   body.name, material.name, material.model));
  }
}

}  // namespace

std::any parse_implicit_solver(const io::YamlReader& reader, const io::YamlMap& solver_map,
                               const SolverDescription& solver, const SceneDescription& scene) {
  refuse_transfers(reader, solver_map, solver);
  refuse_boundaries(scene);
  refuse_materials(scene);
  ImplicitOptions options;
  if (const auto section = solver_map.find("implicit")) read_options(reader, *section, options);
  return options;
}

void check_implicit_scene(const io::YamlReader& reader, const io::YamlMap& top, const SceneDescription&) {
  // contact asks the scheme's traits itself (SchemeTraits::contact)
  if (const auto value = top.find("thermal"))
    reader.fail(*value, "scheme: implicit does not support the thermal section yet");
}

}  // namespace mpm::implicit
