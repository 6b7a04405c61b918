#include "contact_section.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "mpm/contact/multi_velocity_contact.hpp"
#include "mpm/expression.hpp"
#include "mpm/scene_error.hpp"

namespace mpm::contact {
namespace {

/// Reads one YAML node with its dotted key path; every failure names file, line, column and key.
struct Node {
  YAML::Node node;
  std::string key;
  const std::string& file;

  SourceLocation where() const {
    const YAML::Mark m = node.Mark();
    if (m.is_null() || m.line < 0) return {file, 0, 0};
    return {file, m.line + 1, m.column + 1};
  }
  [[noreturn]] void fail(const std::string& message) const { throw SceneError(where(), key, message); }
  Node at(const std::string& name) const { return {node[name], key + "." + name, file}; }
  Node item(std::size_t i) const { return {node[i], key + "[" + std::to_string(i) + "]", file}; }
  bool has(const std::string& name) const { return node.IsMap() && node[name]; }

  void allow(const std::vector<std::string>& keys) const {
    if (!node.IsMap()) fail("expected a map");
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      bool ok = false;
      for (const auto& a : keys) ok |= a == k;
      if (!ok) {
        std::string list;
        for (const auto& a : keys) list += (list.empty() ? "" : ", ") + a;
        throw SceneError(Node{it->first, key + "." + k, file}.where(), key + "." + k,
                         "unknown key '" + k + "'; valid keys: " + list);
      }
    }
  }
  double number() const {
    if (!node.IsScalar()) fail("expected a number");
    try {
      std::size_t used = 0;
      const double x = std::stod(node.Scalar(), &used);
      if (used != node.Scalar().size() || !std::isfinite(x))
        fail("expected a finite number, got '" + node.Scalar() + "'");
      return x;
    } catch (const std::logic_error&) {
      fail("expected a number, got '" + node.Scalar() + "'");
    }
  }
  double non_negative() const {
    const double x = number();
    if (x < 0) fail("must be >= 0, got " + node.Scalar());
    return x;
  }
  std::string text() const {
    if (!node.IsScalar() || node.Scalar().empty()) fail("expected a non-empty string");
    return node.Scalar();
  }
  std::string choice(const std::vector<std::string>& allowed) const {
    const std::string s = text();
    std::string list;
    for (const auto& a : allowed) {
      if (a == s) return s;
      list += (list.empty() ? "" : ", ") + a;
    }
    fail("invalid value '" + s + "'; valid values: " + list);
  }
  /// `dimension` numbers.
  std::array<double, 3> vector(int dimension) const {
    if (!node.IsSequence() || static_cast<int>(node.size()) != dimension)
      fail("expected a list of " + std::to_string(dimension) + " numbers");
    std::array<double, 3> v{0, 0, 0};
    for (int d = 0; d < dimension; ++d) v[d] = item(d).number();
    return v;
  }
  /// `dimension` expressions of t (numbers are expressions too).
  std::array<std::string, 3> expressions(int dimension) const {
    if (!node.IsSequence() || static_cast<int>(node.size()) != dimension)
      fail("expected a list of " + std::to_string(dimension) + " expressions of t");
    std::array<std::string, 3> v{"0", "0", "0"};
    for (int d = 0; d < dimension; ++d) {
      const Node e = item(d);
      v[d] = e.text();
      try {
        Expression(v[d], {"t"});
      } catch (const std::invalid_argument& err) {
        e.fail(std::string(err.what()) + " (variables allowed here: t)");
      }
    }
    return v;
  }
};

int body_index(const SceneDescription& scene, const std::string& name) {
  for (std::size_t k = 0; k < scene.bodies.size(); ++k)
    if (scene.bodies[k].name == name) return static_cast<int>(k);
  return -1;
}

std::string body_name(const Node& n, const SceneDescription& scene) {
  const std::string name = n.text();
  if (body_index(scene, name) < 0) {
    std::string list;
    for (const auto& b : scene.bodies) list += (list.empty() ? "" : ", ") + b.name;
    n.fail("unknown body '" + name + "'; bodies: " + list);
  }
  return name;
}

bool is_rigid(const SceneDescription& scene, const std::string& body) {
  const auto& b = scene.bodies[body_index(scene, body)];
  const auto it = scene.materials.find(b.material);
  return it != scene.materials.end() && it->second.model == "rigid";
}

}  // namespace

std::any parse_contact_section(const YAML::Node& section, const SceneDescription& scene) {
  const Node top{section, "contact", scene.file};
  ContactDescription c;
  c.where = top.where();
  if (section.IsNull()) return c;  // `contact:` alone: frictionless, defaults
  top.allow({"friction", "pairs", "normals", "onset", "rigid_bodies", "planes", "force_file", "force_interval"});
  if (scene.solver.scheme == "tlmpm")
    top.fail("contact needs scheme usl, musl or usf (TLMPM has no contact between bodies)");
  if (scene.solver.velocity_transfer == "apic")  // contact/README.md, limits
    top.fail("contact is not available with velocity_transfer: apic (a block on a contact plane diverges); use flip");
  for (int f = 0; f < 2 * scene.dimension; ++f)
    for (const auto& t : scene.grid.boundary[f].traction)
      if (t) top.fail("face tractions (grid.boundary ... traction) are not supported together with contact");
  if (top.has("friction")) c.friction = top.at("friction").non_negative();
  if (top.has("normals")) c.normals = top.at("normals").choice({"mass_gradient", "density"});
  if (top.has("onset")) c.onset = top.at("onset").choice({"grid", "particle_gap"});
  if (top.has("force_file")) c.force_file = top.at("force_file").text();
  if (top.has("force_interval")) c.force_interval = top.at("force_interval").non_negative();
  if (top.has("pairs")) {
    const Node list = top.at("pairs");
    if (!list.node.IsSequence()) list.fail("expected a list of {bodies: [a, b], friction: mu}");
    for (std::size_t i = 0; i < list.node.size(); ++i) {
      const Node p = list.item(i);
      p.allow({"bodies", "friction"});
      if (!p.has("bodies")) p.fail("missing required key 'bodies'");
      if (!p.has("friction")) p.fail("missing required key 'friction'");
      const Node b = p.at("bodies");
      if (!b.node.IsSequence() || b.node.size() != 2) b.fail("expected a list of two body names");
      PairFriction pf;
      pf.bodies = {body_name(b.item(0), scene), body_name(b.item(1), scene)};
      if (pf.bodies[0] == pf.bodies[1]) b.fail("a pair needs two different bodies");
      pf.friction = p.at("friction").non_negative();
      pf.where = p.where();
      c.pairs.push_back(pf);
    }
  }
  if (top.has("rigid_bodies")) {
    const Node list = top.at("rigid_bodies");
    if (!list.node.IsSequence()) list.fail("expected a list of {body: name, velocity: [...]}");
    std::set<std::string> seen;
    for (std::size_t i = 0; i < list.node.size(); ++i) {
      const Node r = list.item(i);
      r.allow({"body", "velocity"});
      if (!r.has("body")) r.fail("missing required key 'body'");
      RigidBodyDescription rb;
      rb.body = body_name(r.at("body"), scene);
      if (!is_rigid(scene, rb.body))
        r.at("body").fail("body '" + rb.body + "' is not rigid: give it a material with model: rigid");
      if (!seen.insert(rb.body).second) r.at("body").fail("body '" + rb.body + "' is listed twice");
      if (r.has("velocity")) rb.velocity = r.at("velocity").expressions(scene.dimension);
      rb.where = r.where();
      c.rigid_bodies.push_back(rb);
    }
  }
  if (top.has("planes")) {
    const Node list = top.at("planes");
    if (!list.node.IsSequence()) list.fail("expected a list of {point, normal, friction, velocity}");
    for (std::size_t i = 0; i < list.node.size(); ++i) {
      const Node p = list.item(i);
      p.allow({"name", "point", "normal", "friction", "velocity"});
      for (const char* k : {"point", "normal"})
        if (!p.has(k)) p.fail(std::string("missing required key '") + k + "'");
      PlaneDescription pd;
      pd.name = p.has("name") ? p.at("name").text() : "plane_" + std::to_string(i);
      pd.point = p.at("point").vector(scene.dimension);
      pd.normal = p.at("normal").vector(scene.dimension);
      const double len =
          std::sqrt(pd.normal[0] * pd.normal[0] + pd.normal[1] * pd.normal[1] + pd.normal[2] * pd.normal[2]);
      if (!(len > 0)) p.at("normal").fail("the normal must not be zero");
      for (auto& x : pd.normal) x /= len;
      if (p.has("friction")) pd.friction = p.at("friction").non_negative();
      if (p.has("velocity")) pd.velocity = p.at("velocity").expressions(scene.dimension);
      pd.where = p.where();
      c.planes.push_back(pd);
    }
  }
  return c;
}

template <int Dim>
void build_contact(const SceneDescription& scene, Simulation<Dim>& simulation) {
  const auto& c = std::any_cast<const ContactDescription&>(scene.extensions.at("contact"));
  const int n = static_cast<int>(scene.bodies.size());
  ContactSettings<Dim> s;
  s.friction.assign(n * n, c.friction);
  for (const auto& p : c.pairs) {
    const int a = body_index(scene, p.bodies[0]), b = body_index(scene, p.bodies[1]);
    s.friction[a * n + b] = s.friction[b * n + a] = p.friction;
  }
  s.normals = c.normals == "density" ? NormalMethod::density : NormalMethod::mass_gradient;
  s.onset = c.onset == "particle_gap" ? Onset::particle_gap : Onset::grid;
  std::set<int> listed;
  for (const auto& r : c.rigid_bodies) {
    typename ContactSettings<Dim>::Rigid rigid;
    rigid.body = body_index(scene, r.body);
    for (int d = 0; d < Dim; ++d) rigid.velocity[d] = r.velocity[d];
    listed.insert(rigid.body);
    s.rigid_bodies.push_back(rigid);
  }
  for (int k = 0; k < n; ++k)  // rigid bodies not listed stand still
    if (is_rigid(scene, scene.bodies[k].name) && !listed.count(k)) {
      typename ContactSettings<Dim>::Rigid rigid;
      rigid.body = k;
      rigid.velocity.fill("0");
      s.rigid_bodies.push_back(rigid);
    }
  for (const auto& p : c.planes) {
    typename ContactSettings<Dim>::Plane plane;
    plane.name = p.name;
    for (int d = 0; d < Dim; ++d) {
      plane.point[d] = p.point[d];
      plane.normal[d] = p.normal[d];
      plane.velocity[d] = p.velocity[d];
    }
    plane.normal.normalize();
    plane.friction = p.friction;
    s.planes.push_back(plane);
  }
  if (!c.force_file.empty()) s.force_file = (std::filesystem::path(scene.output.directory) / c.force_file).string();
  s.force_interval = c.force_interval;
  try {
    simulation.add_module(std::make_shared<MultiVelocityContact<Dim>>(simulation.grid().geometry, simulation.bodies(),
                                                                      scene.solver.shape_function, s));
  } catch (const std::invalid_argument& e) {
    throw SceneError(c.where, "contact", e.what());
  }
}

template void build_contact<1>(const SceneDescription&, Simulation<1>&);
template void build_contact<2>(const SceneDescription&, Simulation<2>&);
template void build_contact<3>(const SceneDescription&, Simulation<3>&);

}  // namespace mpm::contact
