// The keys of the `contact:` section (docs/scene-reference.md, contact), which contact_section.cpp reads through.
#include "contact_section.hpp"

namespace mpm::contact {
namespace {

using io::KeySpec;
using io::KeyType;
using io::Range;

const char* const conductance_type = "number or `perfect`";
const char* const conductance_allowed = ">= 0 or `perfect`";

std::vector<KeySpec> pair_keys() {
  return {{.name = "bodies",
           .type = KeyType::list,
           .required = true,
           .description = "the two bodies",
           .type_text = "list of 2 body names",
           .allowed_text = "two different bodies"},
          {.name = "friction",
           .type = KeyType::number,
           .unit = "-",
           .range = Range::at_least(0),
           .absent = "the section's `friction`",
           .description = "Coulomb coefficient of the pair"},
          {.name = "thermal_conductance",
           .type = KeyType::number,
           .unit = "W/(m^2 K)",
           .range = Range::at_least(0),
           .absent = "the section's `thermal_conductance`",
           .description = "thermal contact conductance of the pair (a pair gives it, `friction` or both)",
           .type_text = conductance_type,
           .allowed_text = conductance_allowed}};
}

std::vector<KeySpec> rigid_body_keys() {
  return {{.name = "body",
           .type = KeyType::name,
           .required = true,
           .description = "a body whose material has `model: rigid`, listed once",
           .allowed_text = "a rigid body's name"},
          {.name = "velocity",
           .type = KeyType::list,
           .unit = "m/s",
           .absent = "zeros",
           .description = "prescribed velocity, one component per axis",
           .type_text = "list of `dimension` numbers or expressions of `t`",
           .run_control = true}};
}

std::vector<KeySpec> plane_keys() {
  return {{.name = "name",
           .type = KeyType::name,
           .absent = "`plane_<i>` (`i` = position in the list, from 0)",
           .description = "the plane's name in the force file and in reaction histories"},
          {.name = "point",
           .type = KeyType::list,
           .unit = "m",
           .required = true,
           .description = "a point of the plane at t = 0",
           .type_text = "list of `dimension` numbers"},
          {.name = "normal",
           .type = KeyType::list,
           .required = true,
           .description = "out of the wall, towards the bodies; normalised when read",
           .type_text = "list of `dimension` numbers",
           .allowed_text = "not zero"},
          {.name = "friction",
           .type = KeyType::number,
           .unit = "-",
           .range = Range::at_least(0),
           .default_value = 0.0,
           .description = "Coulomb coefficient between the plane and every body"},
          {.name = "velocity",
           .type = KeyType::list,
           .unit = "m/s",
           .absent = "zeros",
           .description = "the plane's velocity, one component per axis",
           .type_text = "list of `dimension` numbers or expressions of `t`",
           .run_control = true}};
}

std::vector<KeySpec> body_boundary_keys() {
  std::vector<KeySpec> keys{{.name = "body",
                             .type = KeyType::name,
                             .required = true,
                             .description = "a deformable body, listed once",
                             .allowed_text = "a body's name, not a rigid one"}};
  for (const char* face : GridDescription::face_names)
    keys.push_back({.name = face,
                    .type = KeyType::choice,
                    .choices = {"fixed", "slip", "free"},
                    .absent = "`grid.boundary`'s condition",
                    .description = "the condition of the body's own field on this face (a face of the scene's "
                                   "dimension)"});
  return keys;
}

}  // namespace

const std::vector<KeySpec>& contact_keys() {
  static const std::vector<KeySpec> keys{
      {.name = "friction",
       .type = KeyType::number,
       .unit = "-",
       .range = Range::at_least(0),
       .default_value = 0.0,
       .description = "Coulomb coefficient of every pair of bodies (eqs 5.6-5.8; 0 = frictionless, eq. 5.5)"},
      {.name = "thermal_conductance",
       .type = KeyType::number,
       .unit = "W/(m^2 K)",
       .range = Range::at_least(0),
       .absent = "`perfect`",
       .description = "thermal contact conductance h of every pair of bodies: the heat flux across their "
                      "interface per kelvin of temperature jump, q = h (T_b - T_a) (theory §12, eqs TC.1-TC.2; "
                      "0 = insulated). Not given: perfect contact, the bodies share the temperature at their common "
                      "nodes (the behaviour without contact). Needs a `thermal:` section",
       .type_text = conductance_type,
       .allowed_text = conductance_allowed},
      {.name = "pairs",
       .type = KeyType::list,
       .absent = "none",
       .description = "`{bodies: [A, B], friction: MU, thermal_conductance: H}`: coefficient and/or conductance of "
                      "one pair (each overrides the section's value; at least one of the two)",
       .keys = pair_keys()},
      {.name = "normals",
       .type = KeyType::choice,
       .choices = {"mass_gradient", "density"},
       .default_value = std::string("mass_gradient"),
       .description = "`mass_gradient` (eq. 5.12) or `density` (cell-centred density, eqs 5.9-5.11)"},
      {.name = "onset",
       .type = KeyType::choice,
       .choices = {"grid", "particle_gap"},
       .default_value = std::string("particle_gap"),
       .description = "`particle_gap`: a node is in contact only if the particles' surfaces (centre ± half the "
                      "particle size along the normal) overlap there, and a node behind a rigid plane only if the "
                      "body's particles reach the plane; `grid`: a node with mass of two approaching bodies is in "
                      "contact (the paper; with `musl` and `usf` two deformable bodies must also approach at the "
                      "start of the step, else the node is released: docs/theory.md §11 \"Energy\"). `grid` "
                      "pushes a body a shape function's reach before it touches a plane or a rigid body (a steel "
                      "block at 50 m/s, 1 mm cells: force from 0.08 us, 1 mm away, +208% energy with cubic "
                      "B-splines) and lets a block resting on another sink 2.7-7 mm in 1 s; `particle_gap`: first "
                      "force at the touch, no sinking (contact/README.md, \"Defaults\")"},
      {.name = "rigid_bodies",
       .type = KeyType::list,
       .absent = "none",
       .description = "`{body: NAME, velocity: [vx, vy(, vz)]}`: prescribed velocity (m/s, expressions of `t`) of a "
                      "body whose material has `model: rigid`; rigid bodies not listed stand still",
       .keys = rigid_body_keys()},
      {.name = "planes",
       .type = KeyType::list,
       .absent = "none",
       .description = "rigid walls, see below",
       .keys = plane_keys()},
      {.name = "body_boundaries",
       .type = KeyType::list,
       .absent = "none",
       .description = "`{body: NAME, FACE: fixed|slip|free, ...}` (faces as in [grid.boundary](#gridboundary)): "
                      "face conditions of one body's own velocity field, see below",
       .keys = body_boundary_keys()},
      {.name = "force_file",
       .type = KeyType::name,
       .absent = "none",
       .description = "CSV of contact forces, written in the output directory",
       .run_control = true},
      {.name = "force_interval",
       .type = KeyType::number,
       .unit = "s",
       .range = Range::at_least(0),
       .default_value = 0.0,
       .description = "time between CSV rows (0: every step); the forces are averaged over the interval",
       .run_control = true},
  };
  return keys;
}

}  // namespace mpm::contact
