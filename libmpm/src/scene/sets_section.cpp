// `sets:` and `conditions:` (docs/scene-reference.md#sets): named particle sets, chosen by body, by a region of
// their initial positions and by id, and what is prescribed on them (held velocity components, a total force, an
// initial velocity, an initial stress). Membership is decided once at t = 0 (sets/particle_sets.hpp); the conditions
// are applied by the set conditions module (sets/set_conditions.hpp).
#include <fmt/format.h>

#include <limits>

#include "mpm/body_shape/shape_kind.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_keys.hpp"
#include "mpm/scene/spec_map.hpp"
#include "mpm/sets/particle_sets.hpp"
#include "sections.hpp"

namespace mpm {

const std::vector<io::KeySpec>& set_keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> keys{
      {.name = "body",
       .type = KeyType::name,
       .absent = "every body",
       .description = "the body, or a list of bodies, whose particles the set takes",
       .type_text = "name or list of names",
       .allowed_text = "names of `bodies`"},
      {.name = "region",
       .type = KeyType::map,
       .absent = "everywhere",
       .description = "the particles whose position at t = 0 lies in this shape (any kind of "
                      "[bodies[].shape](#bodiesshape): box, disk, sphere, cylinder, polygon, mesh, a union, ...)",
       .type_text = "shape"},
      {.name = "ids",
       .type = KeyType::list,
       .absent = "every id",
       .description = "the particles with these ids (the output field `id`, per body from 0 in fill order): numbers "
                      "and ranges `[first, last]` (inclusive)",
       .type_text = "list of ids and `[first, last]` ranges"},
  };
  return keys;
}

const std::vector<io::KeySpec>& condition_keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> keys{
      {.name = "set",
       .type = KeyType::name,
       .required = true,
       .description = "the particle set the condition is on",
       .allowed_text = "a key of `sets`",
       .run_control = true},
      {.name = "velocity",
       .type = KeyType::list,
       .unit = "m/s",
       .absent = "no component held",
       .description = "held velocity per component: a number, an expression of x, y, z (the node's position) and t, "
                      "or `free`; every grid node the set's particles reach moves so (its reaction: a `reaction` "
                      "history with `set:`)",
       .type_text = "list of `dimension` expressions or `free`",
       .run_control = true},
      {.name = "force",
       .type = KeyType::list,
       .unit = "N",
       .absent = "none",
       .description = "total force on the set per component (per metre in 2D, per radian axisymmetric), an "
                      "expression of t; shared by its particles in proportion to their mass",
       .type_text = "list of `dimension` expressions",
       .run_control = true},
      {.name = "initial_velocity",
       .type = KeyType::list,
       .unit = "m/s",
       .absent = "the body's `velocity`",
       .description = "velocity of the set's particles at t = 0, expressions of x, y, z (replaces the body's)",
       .type_text = "list of `dimension` expressions",
       .fork_refusal = "it acts at t = 0: the particles' state at the checkpoint holds it"},
      {.name = "initial_stress",
       .type = KeyType::list,
       .unit = "Pa",
       .absent = "zero stress",
       .description = "Cauchy stress of the set's particles at t = 0, expressions of x, y, z, in the order of the "
                      "output field `stress` (xx, yy, zz in 1D; xx, yy, zz, xy in 2D, axisymmetric rr, zz, "
                      "thetatheta, rz; xx, yy, zz, xy, yz, xz in 3D); or `geostatic`: the state at rest under "
                      "`solver.gravity` (along an axis) below the set's free surface, vertical stress the weight of "
                      "the set's material above the point in its column of cells, horizontal stresses `k0` times it, "
                      "no shear (docs/theory.md eqs 20.1-20.2). For models whose stress is their state "
                      "(hypoelastic: the models marked so in [materials](#materials)); the others refuse it",
       .type_text = "list of 3, 4 or 6 expressions, or `geostatic`",
       .fork_refusal = "it acts at t = 0: the particles' state at the checkpoint holds it"},
      {.name = "k0",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::at_least(0),
       .absent = "each body's model's: Jaky's 1 - sin(friction_angle) for `drucker_prager` and `mohr_coulomb`, 1 - "
                 "sin(atan(mu_s)) for `mu_i`, poisson_ratio / (1 - poisson_ratio) for `linear_elastic`",
       .description = "with `initial_stress: geostatic` only: the coefficient of earth pressure at rest, horizontal "
                      "over vertical stress (eq. 20.2)"},
  };
  return keys;
}

namespace sections {
namespace {

/// `body: NAME` or `body: [A, B]`: body indices, each once.
std::vector<int> read_set_bodies(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  std::vector<std::string> names;
  names.reserve(scene.bodies.size());
  for (const auto& b : scene.bodies) names.push_back(b.name);
  std::vector<YamlValue> items;
  if (value.node.IsSequence())
    items = reader.list(value, std::nullopt, "body names", "");
  else
    items.push_back(value);
  std::vector<int> bodies;
  bodies.reserve(items.size());
  for (const auto& item : items) {
    const std::string name = reader.choice(item, names);
    const int index = static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
    if (std::find(bodies.begin(), bodies.end(), index) != bodies.end())
      reader.fail(item, fmt::format("body '{}' is listed twice", name));
    bodies.push_back(index);
  }
  if (bodies.empty()) reader.fail(value, "give at least one body (or leave `body` out for every body)");
  return bodies;
}

/// `ids: [3, [10, 19], ...]`: inclusive ranges of ids.
std::vector<std::array<std::uint32_t, 2>> read_ids(const YamlReader& reader, const YamlValue& value) {
  const io::Range id_range = io::Range::closed(0, std::numeric_limits<std::uint32_t>::max());
  const auto id = [&](const YamlValue& v) { return static_cast<std::uint32_t>(io::read_integer(reader, v, id_range)); };
  std::vector<std::array<std::uint32_t, 2>> ranges;
  for (const auto& item : reader.list(value, std::nullopt, "ids", "")) {
    if (item.node.IsSequence()) {
      const auto ends = reader.list(item, 2, "ids", "first and last");
      const std::uint32_t first = id(ends[0]), last = id(ends[1]);
      if (last < first) reader.fail(item, fmt::format("the range [{}, {}] is empty: give [first, last]", first, last));
      ranges.push_back({first, last});
    } else {
      const std::uint32_t k = id(item);
      ranges.push_back({k, k});
    }
  }
  if (ranges.empty()) reader.fail(value, "give at least one id (or leave `ids` out for every id)");
  return ranges;
}

SetDescription read_set(const YamlReader& reader, const YamlMap::Entry& entry, const SceneDescription& scene) {
  const io::SpecMap map(reader, entry.value, set_keys());
  SetDescription set;
  set.name = entry.key;
  set.where = reader.location(entry.key_mark);
  for (const auto& b : scene.bodies)
    if (b.name == set.name)
      reader.fail(entry.value, fmt::format("set '{}' has the name of a body: give it another (histories and "
                                           "reactions name bodies and sets alike)",
                                           set.name));
  if (const auto body = map.find("body")) set.bodies = read_set_bodies(reader, *body, scene);
  if (const auto region = map.find("region"))
    set.region = read_body_shape(reader, *region, {.dimension = scene.dimension, .scene_file = scene.file});
  if (const auto ids = map.find("ids")) set.ids = read_ids(reader, *ids);
  return set;
}

/// A list of `dimension` components, each an expression of `variables` (`free` allowed when `may_be_free`).
std::array<std::optional<std::string>, 3> read_components(const YamlReader& reader, const YamlValue& value,
                                                          int dimension, const std::vector<std::string>& variables,
                                                          std::string_view unit, bool may_be_free) {
  std::array<std::optional<std::string>, 3> out;
  const auto items = reader.list(value, static_cast<std::size_t>(dimension), "components");
  for (int d = 0; d < dimension; ++d) {
    const YamlValue& item = items[static_cast<std::size_t>(d)];
    if (may_be_free && item.node.IsScalar() && item.node.Scalar() == "free") continue;
    out[static_cast<std::size_t>(d)] = reader.expression(item, variables, unit);
  }
  return out;
}

/// Fails unless every body of set `set` has a model whose stress is its state (MaterialModel::takes_initial_stress).
void check_initial_stress_models(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene,
                                 int set) {
  std::vector<int> bodies = scene.sets[static_cast<std::size_t>(set)].bodies;
  if (bodies.empty())
    for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b) bodies.push_back(b);
  for (const int b : bodies) {
    const BodyDescription& body = scene.bodies[static_cast<std::size_t>(b)];
    const MaterialDescription& material = scene.materials.at(body.material);
    if (const MaterialModel* model = find_material_model(material.model); !model || !model->takes_initial_stress)
      reader.fail(
          value,
          fmt::format("body '{}' of the set has material '{}' of model {}, whose stress follows from "
                      "its deformation (it has no state to start from); an initial stress is for "
                      "the models whose stress is their state: {}",
                      body.name, material.name, material.model,
                      material_model_names_where([](const MaterialModel& m) { return m.takes_initial_stress; })));
  }
}

/// `initial_stress`: the components of the stress field in this dimension, on bodies whose model takes an initial
/// stress (MaterialModel::takes_initial_stress).
std::array<std::optional<std::string>, 6> read_initial_stress(const YamlReader& reader, const YamlValue& value,
                                                              const SceneDescription& scene, int set) {
  std::array<std::optional<std::string>, 6> out;
  check_initial_stress_models(reader, value, scene, set);
  if (value.node.IsScalar() && value.node.Scalar() == "geostatic") return out;  // sets/geostatic_stress.hpp
  const std::size_t count = scene.dimension == 1 ? 3 : scene.dimension == 2 ? 4 : 6;
  const char* const order = scene.dimension == 1                                  ? "xx, yy, zz"
                            : scene.grid.coordinates == Coordinates::axisymmetric ? "rr, zz, thetatheta, rz"
                            : scene.dimension == 2                                ? "xx, yy, zz, xy"
                                                                                  : "xx, yy, zz, xy, yz, xz";
  if (value.node.IsScalar())
    reader.fail(value, fmt::format("expected a list of {} expressions ({}) or `geostatic`, got '{}'", count, order,
                                   value.node.Scalar()));
  const auto items = reader.list(value, count, "components", order);
  for (std::size_t k = 0; k < count; ++k) out[k] = reader.expression(items[k], {"x", "y", "z"}, "Pa");
  return out;
}

SetConditionDescription read_condition(const YamlReader& reader, const YamlValue& item, const SceneDescription& scene) {
  const io::SpecMap map(reader, item, condition_keys());
  SetConditionDescription c;
  c.where = reader.location(item.mark);
  c.path = item.path;
  const YamlValue set = map.required("set");
  std::vector<std::string> names;
  names.reserve(scene.sets.size());
  for (const auto& s : scene.sets) names.push_back(s.name);
  if (names.empty()) reader.fail(set, "the scene has no `sets:` section to name a set from");
  const std::string name = reader.choice(set, names);
  c.set = static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
  const auto velocity = map.find("velocity"), force = map.find("force"), initial = map.find("initial_velocity");
  const auto stress = map.find("initial_stress");
  if (!velocity && !force && !initial && !stress)
    reader.fail(item, "give what the condition prescribes: velocity, force, initial_velocity or initial_stress");
  const int dim = scene.dimension;
  if (velocity) {
    c.velocity = read_components(reader, *velocity, dim, {"x", "y", "z", "t"}, "m/s", true);
    if (std::none_of(c.velocity.begin(), c.velocity.end(), [](const auto& v) { return v.has_value(); }))
      reader.fail(*velocity, "every component is free: the condition holds nothing");
    if (scene.grid.coordinates == Coordinates::axisymmetric && c.velocity[0] && *c.velocity[0] != "0")
      reader.fail(*velocity,
                  "an axisymmetric run holds the radial velocity only at 0 (a moving radial velocity would need "
                  "a hoop strain the grid does not impose)");
  }
  if (force) c.force = read_components(reader, *force, dim, {"t"}, "N", false);
  if (initial) c.initial_velocity = read_components(reader, *initial, dim, {"x", "y", "z"}, "m/s", false);
  if (stress) {
    c.initial_stress = read_initial_stress(reader, *stress, scene, c.set);
    c.geostatic = stress->node.IsScalar() && stress->node.Scalar() == "geostatic";
  }
  if (const auto k0 = map.find("k0")) {
    if (!c.geostatic) reader.fail(*k0, "k0 is the ratio of a geostatic stress: give it with initial_stress: geostatic");
    c.k0 = map.optional_number("k0");
  }
  if (velocity && force)
    for (int d = 0; d < dim; ++d)
      if (c.velocity[static_cast<std::size_t>(d)] && c.force[static_cast<std::size_t>(d)])
        reader.fail(*force, fmt::format("component {} of the velocity is held, so a force on it does nothing; "
                                        "leave it out (or write `free` for it in velocity)",
                                        axis_names[d]));
  return c;
}

}  // namespace

std::vector<SetDescription> read_sets(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  const YamlMap map = reader.map(value);
  if (map.entries().empty()) reader.fail(value, "give at least one set, or leave `sets` out");
  if (map.entries().size() > static_cast<std::size_t>(max_particle_sets))
    reader.fail(value, fmt::format("at most {} sets, got {}", max_particle_sets, map.entries().size()));
  std::vector<SetDescription> sets;
  sets.reserve(map.entries().size());
  for (const auto& entry : map.entries()) sets.push_back(read_set(reader, entry, scene));
  return sets;
}

std::vector<SetConditionDescription> read_conditions(const YamlReader& reader, const YamlValue& value,
                                                     const SceneDescription& scene) {
  std::vector<SetConditionDescription> conditions;
  for (const auto& item : reader.list(value, std::nullopt, "conditions", "")) {
    SetConditionDescription c = read_condition(reader, item, scene);
    const auto holds = [](const SetConditionDescription& x) {
      return std::any_of(x.velocity.begin(), x.velocity.end(), [](const auto& v) { return v.has_value(); });
    };
    for (const auto& other : conditions)
      if (other.set == c.set && holds(other) && holds(c))
        reader.fail(item, fmt::format("set '{}' has a velocity condition already (line {}): give every held "
                                      "component in one",
                                      scene.sets[static_cast<std::size_t>(c.set)].name, other.where.line));
    conditions.push_back(std::move(c));
  }
  return conditions;
}

}  // namespace sections
}  // namespace mpm
