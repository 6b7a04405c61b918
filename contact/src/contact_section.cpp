#include "contact_section.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include "mpm/boundary/face_condition_kind.hpp"
#include "mpm/contact/multi_velocity_contact.hpp"
#include "mpm/core/closest_name.hpp"
#include "mpm/core/expression.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/spec_map.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "mpm/schemes/scheme_registry.hpp"

namespace mpm::contact {
namespace {

using io::KeySpec;
using io::Range;
using io::SpecMap;
using io::YamlReader;
using io::YamlValue;

int body_index(const SceneDescription& scene, const std::string& name) {
  for (std::size_t k = 0; k < scene.bodies.size(); ++k)
    if (scene.bodies[k].name == name) return static_cast<int>(k);
  return -1;
}

/// The name of one of the scene's bodies.
std::string body_name(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  const std::string name = reader.name(value);
  if (body_index(scene, name) < 0) {
    std::vector<std::string> names;
    for (const auto& body : scene.bodies) names.push_back(body.name);
    reader.fail(
        value, fmt::format("unknown body '{}'{}; bodies: {}", name, did_you_mean(name, names), fmt::join(names, ", ")));
  }
  return name;
}

bool is_rigid(const SceneDescription& scene, const std::string& body) {
  const auto& description = scene.bodies[body_index(scene, body)];
  const auto it = scene.materials.find(description.material);
  return it != scene.materials.end() && it->second.model == "rigid";
}

/// `dimension` velocity components, expressions of t (m/s).
std::array<std::string, 3> velocity(const YamlReader& reader, const YamlValue& value, int dimension) {
  std::array<std::string, 3> components{"0", "0", "0"};
  const auto items = reader.list(value, dimension, "components");
  for (int d = 0; d < dimension; ++d) components[d] = reader.expression(items[d], {"t"}, "m/s");
  return components;
}

/// The keys of the entries of the section's list `key`.
const std::vector<KeySpec>& entry_keys(const char* key) { return io::find_key(contact_keys(), key)->keys; }

/// A thermal contact conductance, W/(m^2 K): a number in the spec's range, or `perfect` (+infinity: the bodies
/// share the temperature at their common nodes).
double read_conductance(const SpecMap& map, const YamlValue& value) {
  if (value.node.IsScalar() && value.node.Scalar() == "perfect") return std::numeric_limits<double>::infinity();
  const KeySpec& spec = map.spec("thermal_conductance");
  return map.reader().number(value, spec.range, spec.unit);
}

/// Fails when the scene's other choices exclude contact (contact/README.md, limits).
void check_solver(const YamlReader& reader, const YamlValue& section, const SceneDescription& scene) {
  if (const Support& contact = scheme_of(scene.solver).traits.contact; !contact)
    reader.fail(section,
                fmt::format("contact needs scheme {} ({})",
                            scheme_names_where([](const SchemeTraits& t) { return t.contact.yes; }), contact.why_not));
  for (int f = 0; f < 2 * scene.dimension; ++f)
    if (const std::string why = face_traits(scene.grid.boundary[static_cast<std::size_t>(f)]).not_contact; !why.empty())
      reader.fail(section, why);
}

std::vector<PairFriction> read_pairs(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  std::vector<PairFriction> pairs;
  for (const auto& item :
       reader.list(value, std::nullopt, "pairs {bodies: [a, b], friction: mu, thermal_conductance: h}")) {
    const SpecMap map(reader, item, entry_keys("pairs"));
    const YamlValue bodies = map.required("bodies");
    const auto friction = map.find("friction");
    const auto conductance = map.find("thermal_conductance");
    if (!friction && !conductance)  // a pair sets at least one of the two
      map.map().required("friction", "key", " (a pair gives friction, thermal_conductance or both)");
    const auto names = reader.list(bodies, 2, "body names", "");
    PairFriction pair;
    pair.bodies = {body_name(reader, names[0], scene), body_name(reader, names[1], scene)};
    if (pair.bodies[0] == pair.bodies[1]) reader.fail(bodies, "a pair needs two different bodies");
    pair.friction = map.optional_number("friction");
    if (conductance) pair.thermal_conductance = read_conductance(map, *conductance);
    pair.where = reader.location(item.mark);
    pairs.push_back(pair);
  }
  return pairs;
}

std::vector<RigidBodyDescription> read_rigid_bodies(const YamlReader& reader, const YamlValue& value,
                                                    const SceneDescription& scene) {
  std::vector<RigidBodyDescription> rigid_bodies;
  std::set<std::string> seen;
  for (const auto& item : reader.list(value, std::nullopt, "rigid bodies {body: name, velocity: [...]}")) {
    const SpecMap map(reader, item, entry_keys("rigid_bodies"));
    const YamlValue body = map.required("body");
    RigidBodyDescription rigid;
    rigid.body = body_name(reader, body, scene);
    if (!is_rigid(scene, rigid.body))
      reader.fail(body, "body '" + rigid.body + "' is not rigid: give it a material with model: rigid");
    if (!seen.insert(rigid.body).second) reader.fail(body, "body '" + rigid.body + "' is listed twice");
    if (const auto v = map.find("velocity")) {
      rigid.velocity = velocity(reader, *v, scene.dimension);
      const Expression radial(rigid.velocity[0], {"t"});
      if (scene.grid.coordinates == Coordinates::axisymmetric &&
          !(radial.is_constant() && radial.constant_value() == 0))
        reader.fail(*v,
                    "in axisymmetric coordinates a rigid body cannot move radially (its ring would stretch): "
                    "the radial velocity (the first component) must be 0");
    }
    rigid.where = reader.location(item.mark);
    rigid_bodies.push_back(rigid);
  }
  return rigid_bodies;
}

std::vector<PlaneDescription> read_planes(const YamlReader& reader, const YamlValue& value,
                                          const SceneDescription& scene) {
  std::vector<PlaneDescription> planes;
  const auto items = reader.list(value, std::nullopt, "planes {point, normal, friction, velocity}");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const SpecMap map(reader, items[i], entry_keys("planes"));
    const YamlValue point = map.required("point");
    const YamlValue normal = map.required("normal");
    PlaneDescription plane;
    const auto name = map.find("name");
    plane.name = name ? reader.name(*name) : "plane_" + std::to_string(i);
    plane.point = reader.vector(point, scene.dimension, Range::any(), "m");
    plane.normal = reader.vector(normal, scene.dimension, Range::any(), "");
    const double length = std::hypot(plane.normal[0], plane.normal[1], plane.normal[2]);
    if (!(length > 0)) reader.fail(normal, "the normal must not be zero");
    for (auto& component : plane.normal) component /= length;
    if (scene.grid.coordinates == Coordinates::axisymmetric && plane.normal[0] != 0)
      reader.fail(normal,
                  "in axisymmetric coordinates a rigid plane must be normal to the axis, normal [0, 1] or "
                  "[0, -1] (a tilted plane would revolve into a cone)");
    plane.friction = map.number("friction");
    if (const auto v = map.find("velocity")) plane.velocity = velocity(reader, *v, scene.dimension);
    plane.where = reader.location(items[i].mark);
    planes.push_back(plane);
  }
  return planes;
}

/// `body_boundaries`: per body, face conditions of its own field that replace grid.boundary's on the faces given
/// (`fixed`, `slip` or `free`: velocity conditions that hold a component at 0, so they do no work).
std::vector<BodyBoundaryDescription> read_body_boundaries(const YamlReader& reader, const YamlValue& value,
                                                          const SceneDescription& scene) {
  std::vector<BodyBoundaryDescription> result;
  std::set<std::string> seen;
  const auto& names = GridDescription::face_names;
  const std::vector<std::string> faces(names.begin(), names.begin() + std::ptrdiff_t{2} * scene.dimension);
  const auto& all_keys = entry_keys("body_boundaries");  // body, then the faces
  const std::vector<KeySpec> keys(all_keys.begin(), all_keys.begin() + 1 + std::ptrdiff_t{2} * scene.dimension);
  for (const auto& item : reader.list(value, std::nullopt, "body boundaries {body: name, FACE: fixed|slip|free}")) {
    const SpecMap map(reader, item, keys, {}, "key", fmt::format(" (body and the faces of {}D)", scene.dimension));
    const YamlValue body = map.required("body");
    BodyBoundaryDescription own;
    own.body = body_name(reader, body, scene);
    if (is_rigid(scene, own.body))
      reader.fail(body, "body '" + own.body +
                            "' is rigid: its velocity is prescribed on every node it touches (contact.rigid_bodies), "
                            "face conditions would contradict it");
    if (!seen.insert(own.body).second) reader.fail(body, "body '" + own.body + "' is listed twice");
    bool any = false;
    for (const auto& entry : map.map().entries()) {
      if (entry.key == "body") continue;
      const int index = static_cast<int>(std::find(faces.begin(), faces.end(), entry.key) - faces.begin());
      if (!entry.value.node.IsScalar())
        reader.fail(entry.value, "expected fixed, slip or free (conditions that hold a velocity component at 0), got " +
                                     io::describe(entry.value.node));
      const std::string kind = reader.choice(entry.value, map.spec(entry.key).choices);
      if (index == 0 && scene.grid.coordinates == Coordinates::axisymmetric && kind != "slip")
        reader.fail(entry.value,
                    "in axisymmetric coordinates the face x_min is the axis: its radial velocity is held "
                    "for every body (only slip may be written)");
      own.faces[index] =
          read_face_condition(reader, entry.value, FaceContext{scene.dimension, index, scene.grid.extent});
      any = true;
    }
    if (!any)
      reader.fail(item, fmt::format("give at least one face ({}) with fixed, slip or free", fmt::join(faces, ", ")));
    own.where = reader.location(item.mark);
    result.push_back(own);
  }
  return result;
}

}  // namespace

std::any parse_contact_section(const YamlReader& reader, const YamlValue& section, const SceneDescription& scene) {
  ContactDescription contact;
  contact.where = reader.location(section.mark);
  if (section.node.IsNull()) return contact;  // `contact:` alone: frictionless, defaults
  const SpecMap map(reader, section, contact_keys());
  check_solver(reader, section, scene);
  contact.friction = map.number("friction");
  if (const auto conductance = map.find("thermal_conductance")) {
    contact.thermal_conductance = read_conductance(map, *conductance);
    contact.thermal_conductance_where = reader.location(conductance->mark);
  }
  contact.normals = map.choice("normals");
  contact.onset = map.choice("onset");
  if (const auto file = map.find("force_file")) contact.force_file = reader.name(*file);
  contact.force_interval = map.number("force_interval");
  if (const auto pairs = map.find("pairs")) contact.pairs = read_pairs(reader, *pairs, scene);
  if (const auto rigid = map.find("rigid_bodies")) contact.rigid_bodies = read_rigid_bodies(reader, *rigid, scene);
  if (const auto planes = map.find("planes")) contact.planes = read_planes(reader, *planes, scene);
  if (const auto own = map.find("body_boundaries")) contact.body_boundaries = read_body_boundaries(reader, *own, scene);
  return contact;
}

void complete_contact_defaults(SceneDescription& scene) {
  if (!scene.solver.velocity_transfer_given && scheme_of(scene.solver).traits.affine_transfers)
    scene.solver.velocity_transfer = VelocityTransfer::apic;
}

namespace {

/// The pairs' thermal contact conductances (n x n, W/(m^2 K)), or none when every pair is perfect (the default:
/// the bodies then share the temperature at their common nodes, as without contact). Refused without a
/// thermal: section (nothing would conduct heat).
std::vector<Real> thermal_conductance(const SceneDescription& scene, const ContactDescription& contact) {
  const int body_count = static_cast<int>(scene.bodies.size());
  int given = -1;  // the first pair that gives one
  for (std::size_t k = 0; k < contact.pairs.size() && given < 0; ++k)
    if (contact.pairs[k].thermal_conductance) given = static_cast<int>(k);
  if (!contact.thermal_conductance && given < 0) return {};
  if (!scene.extensions.count("thermal")) {
    const std::string why = "a thermal contact conductance needs heat conduction: add a thermal: section";
    if (contact.thermal_conductance)
      throw SceneError(contact.thermal_conductance_where, "contact.thermal_conductance", why);
    throw SceneError(contact.pairs[given].where, fmt::format("contact.pairs[{}].thermal_conductance", given), why);
  }
  std::vector<Real> h(body_count * body_count,
                      contact.thermal_conductance.value_or(std::numeric_limits<Real>::infinity()));
  for (const auto& pair : contact.pairs) {
    if (!pair.thermal_conductance) continue;
    const int a = body_index(scene, pair.bodies[0]), b = body_index(scene, pair.bodies[1]);
    h[a * body_count + b] = h[b * body_count + a] = *pair.thermal_conductance;
  }
  return h;
}

}  // namespace

template <int Dim>
void build_contact(const SceneDescription& scene, Simulation<Dim>& simulation) {
  const auto& contact = std::any_cast<const ContactDescription&>(scene.extensions.at("contact"));
  const int body_count = static_cast<int>(scene.bodies.size());
  ContactSettings<Dim> settings;
  settings.friction.assign(body_count * body_count, contact.friction);
  for (const auto& pair : contact.pairs) {
    const int a = body_index(scene, pair.bodies[0]), b = body_index(scene, pair.bodies[1]);
    if (pair.friction) settings.friction[a * body_count + b] = settings.friction[b * body_count + a] = *pair.friction;
  }
  settings.thermal_conductance = thermal_conductance(scene, contact);
  settings.normals = contact.normals == "density" ? NormalMethod::density : NormalMethod::mass_gradient;
  settings.onset = contact.onset == "particle_gap" ? Onset::particle_gap : Onset::grid;
  std::set<int> listed;
  for (const auto& described : contact.rigid_bodies) {
    typename ContactSettings<Dim>::Rigid rigid;
    rigid.body = body_index(scene, described.body);
    for (int d = 0; d < Dim; ++d) rigid.velocity[d] = described.velocity[d];
    listed.insert(rigid.body);
    settings.rigid_bodies.push_back(rigid);
  }
  for (int k = 0; k < body_count; ++k)  // rigid bodies not listed stand still
    if (is_rigid(scene, scene.bodies[k].name) && !listed.count(k)) {
      typename ContactSettings<Dim>::Rigid rigid;
      rigid.body = k;
      rigid.velocity.fill("0");
      settings.rigid_bodies.push_back(rigid);
    }
  for (const auto& described : contact.planes) {
    typename ContactSettings<Dim>::Plane plane;
    plane.name = described.name;
    for (int d = 0; d < Dim; ++d) {
      plane.point[d] = described.point[d];
      plane.normal[d] = described.normal[d];
      plane.velocity[d] = described.velocity[d];
    }
    plane.normal.normalize();
    plane.friction = described.friction;
    settings.planes.push_back(plane);
  }
  for (const auto& described : contact.body_boundaries) {
    typename ContactSettings<Dim>::BodyFaces own;
    own.body = body_index(scene, described.body);
    std::array<FaceDescription, 6> faces = scene.grid.boundary;  // the scene's faces, the body's replacements over them
    for (int f = 0; f < 2 * Dim; ++f)
      if (described.faces[f]) faces[f] = *described.faces[f];
    own.boundary =
        std::make_shared<const GridBoundary<Dim>>(make_grid_boundary<Dim>(simulation.grid().geometry, faces));
    settings.body_faces.push_back(own);
  }
  if (!contact.force_file.empty())
    settings.force_file = (std::filesystem::path(scene.output.directory) / contact.force_file).string();
  settings.force_interval = contact.force_interval;
  // The node criterion also corrects nodes between bodies that are still apart; there MUSL and USF (whose kinetic
  // energy changes by J.v^t) gained energy from impulses on bodies separating at v^t: such nodes are released
  // (docs/theory.md §11, "Energy"). USL is dissipative with contact, and the particle gap only corrects where the
  // particles touch: both keep the paper's test.
  settings.release_on_start =
      settings.onset == Onset::grid && scheme_of(scene.solver).traits.contact_releases_separating_nodes;
  try {
    simulation.add_module(std::make_shared<MultiVelocityContact<Dim>>(simulation.grid().geometry, simulation.bodies(),
                                                                      scene.solver.shape_function, settings));
  } catch (const std::invalid_argument& e) {
    throw SceneError(contact.where, "contact", e.what());
  }
}

template void build_contact<1>(const SceneDescription&, Simulation<1>&);
template void build_contact<2>(const SceneDescription&, Simulation<2>&);
template void build_contact<3>(const SceneDescription&, Simulation<3>&);

}  // namespace mpm::contact
