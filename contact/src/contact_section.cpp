#include "contact_section.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include "mpm/contact/multi_velocity_contact.hpp"
#include "mpm/expression.hpp"
#include "mpm/io/yaml_reader.hpp"
#include "mpm/scene_error.hpp"
#include "mpm/scheme_registry.hpp"

namespace mpm::contact {
namespace {

using io::Range;
using io::YamlMap;
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
    reader.fail(value, fmt::format("unknown body '{}'; bodies: {}", name, fmt::join(names, ", ")));
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
  for (int d = 0; d < dimension; ++d) components[d] = reader.expression(items[d], {"t"});
  return components;
}

/// A thermal contact conductance, W/(m^2 K): a number >= 0, or `perfect` (+infinity: the bodies share the
/// temperature at their common nodes).
double read_conductance(const YamlReader& reader, const YamlValue& value) {
  if (value.node.IsScalar() && value.node.Scalar() == "perfect") return std::numeric_limits<double>::infinity();
  return reader.number(value, Range::at_least(0), "W/(m^2 K)");
}

/// Fails when the scene's other choices exclude contact (contact/README.md, limits).
void check_solver(const YamlReader& reader, const YamlValue& section, const SceneDescription& scene) {
  if (const Support& contact = scheme_of(scene.solver).traits.contact; !contact)
    reader.fail(section,
                fmt::format("contact needs scheme {} ({})",
                            scheme_names_where([](const SchemeTraits& t) { return t.contact.yes; }), contact.why_not));
  for (int f = 0; f < 2 * scene.dimension; ++f)
    for (const auto& traction : scene.grid.boundary[f].traction)
      if (traction)
        reader.fail(section,
                    "face tractions (grid.boundary ... traction) are not supported together with contact: a traction "
                    "acts on the shared grid field, and contact gives every body its own");
}

std::vector<PairFriction> read_pairs(const YamlReader& reader, const YamlValue& value, const SceneDescription& scene) {
  std::vector<PairFriction> pairs;
  for (const auto& item :
       reader.list(value, std::nullopt, "pairs {bodies: [a, b], friction: mu, thermal_conductance: h}")) {
    const YamlMap map = reader.map(item);
    map.allow({"bodies", "friction", "thermal_conductance"});
    const YamlValue bodies = map.required("bodies");
    const auto friction = map.find("friction");
    const auto conductance = map.find("thermal_conductance");
    if (!friction && !conductance)  // a pair sets at least one of the two
      map.required("friction", "key", " (a pair gives friction, thermal_conductance or both)");
    const auto names = reader.list(bodies, 2, "body names", "");
    PairFriction pair;
    pair.bodies = {body_name(reader, names[0], scene), body_name(reader, names[1], scene)};
    if (pair.bodies[0] == pair.bodies[1]) reader.fail(bodies, "a pair needs two different bodies");
    if (friction) pair.friction = reader.number(*friction, Range::at_least(0), "");
    if (conductance) pair.thermal_conductance = read_conductance(reader, *conductance);
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
    const YamlMap map = reader.map(item);
    map.allow({"body", "velocity"});
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
    const YamlMap map = reader.map(items[i]);
    map.allow({"name", "point", "normal", "friction", "velocity"});
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
    if (const auto friction = map.find("friction")) plane.friction = reader.number(*friction, Range::at_least(0), "");
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
  for (const auto& item : reader.list(value, std::nullopt, "body boundaries {body: name, FACE: fixed|slip|free}")) {
    const YamlMap map = reader.map(item);
    std::vector<std::string> keys{"body"};
    keys.insert(keys.end(), faces.begin(), faces.end());
    map.allow(keys, "key", fmt::format(" (body and the faces of {}D)", scene.dimension));
    const YamlValue body = map.required("body");
    BodyBoundaryDescription own;
    own.body = body_name(reader, body, scene);
    if (is_rigid(scene, own.body))
      reader.fail(body, "body '" + own.body +
                            "' is rigid: its velocity is prescribed on every node it touches (contact.rigid_bodies), "
                            "face conditions would contradict it");
    if (!seen.insert(own.body).second) reader.fail(body, "body '" + own.body + "' is listed twice");
    bool any = false;
    for (const auto& entry : map.entries()) {
      if (entry.key == "body") continue;
      const int index = static_cast<int>(std::find(faces.begin(), faces.end(), entry.key) - faces.begin());
      const int normal_axis = index / 2;
      if (!entry.value.node.IsScalar())
        reader.fail(entry.value, "expected fixed, slip or free (conditions that hold a velocity component at 0), got " +
                                     io::describe(entry.value.node));
      const std::string kind = reader.choice(entry.value, {"fixed", "slip", "free"});
      if (index == 0 && scene.grid.coordinates == Coordinates::axisymmetric && kind != "slip")
        reader.fail(entry.value,
                    "in axisymmetric coordinates the face x_min is the axis: its radial velocity is held "
                    "for every body (only slip may be written)");
      FaceBoundary face;
      face.where = reader.location(entry.value.mark);
      const ComponentConstraint held{std::in_place, "0"};
      if (kind == "fixed")
        for (int d = 0; d < scene.dimension; ++d) face.component[d] = held;
      else if (kind == "slip")
        face.component[normal_axis] = held;
      own.faces[index] = face;
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
  const YamlMap map = reader.map(section);
  map.allow({"friction", "thermal_conductance", "pairs", "normals", "onset", "rigid_bodies", "planes",
             "body_boundaries", "force_file", "force_interval"});
  check_solver(reader, section, scene);
  if (const auto friction = map.find("friction")) contact.friction = reader.number(*friction, Range::at_least(0), "");
  if (const auto conductance = map.find("thermal_conductance")) {
    contact.thermal_conductance = read_conductance(reader, *conductance);
    contact.thermal_conductance_where = reader.location(conductance->mark);
  }
  if (const auto normals = map.find("normals")) contact.normals = reader.choice(*normals, {"mass_gradient", "density"});
  if (const auto onset = map.find("onset")) contact.onset = reader.choice(*onset, {"grid", "particle_gap"});
  if (const auto file = map.find("force_file")) contact.force_file = reader.name(*file);
  if (const auto interval = map.find("force_interval"))
    contact.force_interval = reader.number(*interval, Range::at_least(0), "s");
  if (const auto pairs = map.find("pairs")) contact.pairs = read_pairs(reader, *pairs, scene);
  if (const auto rigid = map.find("rigid_bodies")) contact.rigid_bodies = read_rigid_bodies(reader, *rigid, scene);
  if (const auto planes = map.find("planes")) contact.planes = read_planes(reader, *planes, scene);
  if (const auto own = map.find("body_boundaries")) contact.body_boundaries = read_body_boundaries(reader, *own, scene);
  return contact;
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
    own.faces = scene.grid.boundary;  // the scene's faces, the body's replacements over them
    for (int f = 0; f < 2 * Dim; ++f)
      if (described.faces[f]) own.faces[f] = *described.faces[f];
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
