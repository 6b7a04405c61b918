// `solver.scheme: implicit` (docs/scene-reference.md, solver.implicit): the options of the Newton-Krylov solve
// and what the implicit scheme refuses, each at its key (file:line:column, exit 2).
#include "implicit_section.hpp"

#include <fmt/format.h>

#include "mpm/boundary/face_condition_kind.hpp"
#include "mpm/implicit/implicit_options.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/spec_map.hpp"
#include "mpm/schemes/scheme.hpp"

namespace mpm::implicit {
namespace {

using io::Range;

void read_options(const io::YamlReader& reader, const io::YamlValue& value, ImplicitOptions& o) {
  const std::vector<io::KeySpec>& keys = implicit_keys().front().keys;
  const io::SpecMap map(reader, value, keys);
  o.newton_rtol = map.number("newton_rtol");
  o.newton_atol = map.number("newton_atol");
  o.max_newton_iterations = map.integer("max_newton_iterations");
  o.linear_rtol = map.number("linear_rtol");
  o.max_linear_iterations = map.integer("max_linear_iterations");
  o.gmres_restart = map.integer("gmres_restart");
  o.mass_rtol = map.number("mass_rtol");
  o.volumetric = *enum_from_name<VolumetricMode>(map.choice("volumetric"));
  o.weak_node_fraction = map.number("weak_node_fraction");
  o.newton_trace = map.boolean("newton_trace");
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

const std::vector<io::KeySpec>& implicit_keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> keys{
      {.name = "implicit",
       .type = KeyType::map,
       .absent = "every key's default",
       .description = "the options of the Newton-Krylov solve, see [solver.implicit](#solverimplicit)",
       .keys =
           {{.name = "newton_rtol",
             .type = KeyType::number,
             .unit = "-",
             .range = Range::open(0, 1),
             .default_value = 1e-10,
             .description =
                 "Newton stops at ‖R‖ ≤ newton_rtol · R_ref, with the reference residual R_ref = ‖2 M v_n/Δt‖ + "
                 "‖F^int(predictor)‖ + ‖F^ext‖ (the sizes of the residual's terms at the predictor, free degrees of "
                 "freedom); or where no step reduces ‖R‖ any more while the Newton update is below 10⁻⁸ of the "
                 "unknowns (the residual's rounding floor, theory.md §15)"},
            {.name = "newton_atol",
             .type = KeyType::number,
             .unit = "N",
             .range = Range::at_least(0),
             .default_value = 0.0,
             .description = "or at ‖R‖ ≤ newton_atol"},
            {.name = "max_newton_iterations",
             .type = KeyType::integer,
             .range = Range::at_least(1),
             .default_value = 25.0,
             .description = "not converged by then: the run stops (exit 3) with the last good state written, naming "
                            "step, time, ‖R‖, iterations and tolerance"},
            {.name = "linear_rtol",
             .type = KeyType::number,
             .unit = "-",
             .range = Range::open(0, 1),
             .default_value = 1e-4,
             .description = "GMRES relative tolerance of each Newton direction"},
            {.name = "max_linear_iterations",
             .type = KeyType::integer,
             .range = Range::at_least(1),
             .default_value = 200.0,
             .description = "GMRES iterations per Newton direction at most"},
            {.name = "gmres_restart",
             .type = KeyType::integer,
             .range = Range::at_least(1),
             .default_value = 50.0,
             .description = "GMRES restart length"},
            {.name = "mass_rtol",
             .type = KeyType::number,
             .unit = "-",
             .range = Range::open(0, 1),
             .default_value = 1e-12,
             .description = "conjugate-gradient tolerance of the projection (87), relative to ‖Σ N π‖"},
            {.name = "volumetric",
             .type = KeyType::choice,
             .choices = enum_names<VolumetricMode>(),
             .default_value = std::string("mixed_cell"),
             .description = "`mixed_cell`: Q1/P0 three-field volume per cell (88c)-(88e); `pointwise`: Θ = J per "
                            "particle"},
            {.name = "weak_node_fraction",
             .type = KeyType::number,
             .unit = "-",
             .range = Range::closed(0, 1),
             .default_value = 0.1,
             .description =
                 "a node whose particles cover less than this fraction of a cell (Σ N^A V_p / h^dim) is weak: its "
                 "velocity components are extrapolated linearly from the two nodes further in along a grid axis "
                 "(u_A = 2u_B − u_C), the same prolongation in (87) and (88a), which keeps the energy identity and "
                 "both momenta (docs/theory.md §15, \"Weak nodes\"); 0 keeps every node"},
            {.name = "newton_trace",
             .type = KeyType::boolean,
             .default_value = false,
             .description = "print every Newton iteration (‖R‖ before and after, step length, GMRES iterations, the "
                            "worst degree of freedom), each step's weak-node split and, when a solve fails, the "
                            "degrees of freedom where the residual stays, to stderr; the results are the same bits"}}},
  };
  return keys;
}

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
