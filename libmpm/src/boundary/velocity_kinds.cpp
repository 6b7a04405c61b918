// The velocity and traction kinds of grid.boundary (docs/scene-reference.md, grid): `fixed` (every velocity
// component held at 0), `slip` (the normal one), `free` and `stop` (no condition), and `prescribed`
// (`{velocity: [...], traction: [...]}`, each component an expression of t or `free`). All but free and stop make a
// VelocityFace (mpm/boundary/velocity_face.hpp).
#include <fmt/format.h>

#include "kinds.hpp"
#include "mpm/boundary/face.hpp"
#include "mpm/boundary/velocity_face.hpp"
#include "mpm/core/expression.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::boundary {
namespace {

constexpr const char* axis_names = "xyz";

template <int Dim>
std::unique_ptr<FaceCondition<Dim>> make_velocity_face(const std::any& spec, const GridGeometry<Dim>& g, int face) {
  return std::make_unique<VelocityFace<Dim>>(g, face, std::any_cast<const VelocityFaceSpec&>(spec));
}

template <int Dim>
std::unique_ptr<FaceCondition<Dim>> make_nothing(const std::any&, const GridGeometry<Dim>&, int) {
  return nullptr;
}

FaceTraits velocity_traits(const std::any& spec) {
  const auto& s = std::any_cast<const VelocityFaceSpec&>(spec);
  FaceTraits t;
  for (int d = 0; d < 3; ++d) {
    if (const auto& v = s.velocity[d]) {
      t.holds_velocity = true;
      const Expression e(*v, {"t"});
      if (!(e.is_constant() && e.constant_value() == 0)) t.does_work = true;
      if (*v != "0" && t.not_implicit.empty())
        t.not_implicit = fmt::format(
            "scheme: implicit supports walls at rest only (fixed, slip or velocity 0); component {} is '{}'",
            axis_names[d], *v);
    }
    if (s.traction[d]) {
      t.traction = t.does_work = true;
      if (t.not_implicit.empty()) t.not_implicit = "scheme: implicit does not support tractions yet";
    }
  }
  return t;
}

FaceTraits no_traits(const std::any&) { return {}; }

/// A kind that holds the velocity components `held(face, dimension)` at 0.
template <class Held>
FaceConditionKind at_rest_kind(std::string name, std::string description, Held) {
  FaceConditionKind k;
  k.name = std::move(name);
  k.description = std::move(description);
  k.parse = [](const io::YamlReader& reader, const io::YamlValue& value, const FaceContext& face) -> std::any {
    allow_keys(reader, value, {});
    VelocityFaceSpec spec;
    // the held components as the expression "0" (built by count: GCC 12 warns on copying the literal here)
    for (int d : Held{}(face.face, face.dimension)) spec.velocity[d].emplace(1, '0');
    return spec;
  };
  k.traits = velocity_traits;
  k.make_1d = make_velocity_face<1>;
  k.make_2d = make_velocity_face<2>;
  k.make_3d = make_velocity_face<3>;
  return k;
}

struct Every {
  std::vector<int> operator()(int, int dimension) const {
    std::vector<int> all(static_cast<std::size_t>(dimension));
    for (int d = 0; d < dimension; ++d) all[static_cast<std::size_t>(d)] = d;
    return all;
  }
};
struct Normal {
  std::vector<int> operator()(int face, int) const { return {face_axis(face)}; }
};

FaceConditionKind nothing_kind(std::string name, std::string description) {
  FaceConditionKind k;
  k.name = std::move(name);
  k.description = std::move(description);
  k.parse = [](const io::YamlReader& reader, const io::YamlValue& value, const FaceContext&) -> std::any {
    allow_keys(reader, value, {});
    return {};
  };
  k.traits = no_traits;
  k.make_1d = make_nothing<1>;
  k.make_2d = make_nothing<2>;
  k.make_3d = make_nothing<3>;
  return k;
}

/// `{velocity: [...], traction: [...]}`: per component an expression of t, or `free`.
std::any parse_prescribed(const io::YamlReader& reader, const io::YamlValue& value, const FaceContext& face) {
  if (!value.node.IsMap())
    reader.fail(value, "expected {velocity: [...]} and/or {traction: [...]}, got " + io::describe(value.node));
  const io::YamlMap condition = reader.map(value);
  condition.allow({"velocity", "traction", "type"});
  const auto velocity = condition.find("velocity");
  const auto traction = condition.find("traction");
  if (!velocity && !traction) reader.fail(value, "expected velocity: [...] and/or traction: [...]");
  VelocityFaceSpec spec;
  if (velocity) {
    const auto components = reader.list(*velocity, face.dimension, "components");
    for (int d = 0; d < face.dimension; ++d) {
      if (components[d].node.IsScalar() && components[d].node.Scalar() == "free") continue;
      spec.velocity[d] = reader.expression(components[d], {"t"}, "m/s");
    }
  }
  if (traction) {
    const auto components = reader.list(*traction, face.dimension, "components");
    for (int d = 0; d < face.dimension; ++d) {
      if (spec.velocity[d])
        reader.fail(components[d], fmt::format("component {} of face {} has both a velocity and a traction",
                                               axis_names[d], face_names[static_cast<std::size_t>(face.face)]));
      spec.traction[d] = reader.expression(components[d], {"t"}, "Pa");
    }
  }
  return spec;
}

}  // namespace

void allow_keys(const io::YamlReader& reader, const io::YamlValue& value, std::vector<std::string> keys) {
  if (value.node.IsScalar()) return;
  keys.push_back("type");
  reader.map(value).allow(keys);
}

FaceConditionKind fixed_kind() {
  return at_rest_kind("fixed", "every velocity component of the face's nodes held at 0 (a wall without slip)", Every{});
}

FaceConditionKind slip_kind() {
  return at_rest_kind("slip", "the normal velocity held at 0, the tangential ones free (a frictionless wall)",
                      Normal{});
}

FaceConditionKind free_kind() {
  return nothing_kind("free",
                      "no velocity condition; a particle that crosses the face stops the run, as with stop (the "
                      "default of a face not listed)");
}

FaceConditionKind stop_kind() {
  return nothing_kind("stop",
                      "no velocity condition, and a particle that crosses the face stops the run through the "
                      "stability guard (the default, written out)");
}

FaceConditionKind prescribed_kind() {
  FaceConditionKind k;
  k.name = "prescribed";
  k.description =
      "per component a velocity (m/s) or a traction (Pa), each an expression of t or free; a map without type "
      "is this kind";
  k.keys = {{"velocity", "m/s", "per component an expression of t (s), or free; 0 holds the component at rest"},
            {"traction", "Pa", "per component an expression of t (s): a force per area on the face's nodes"}};
  k.bare = false;
  k.parse = parse_prescribed;
  k.traits = velocity_traits;
  k.make_1d = make_velocity_face<1>;
  k.make_2d = make_velocity_face<2>;
  k.make_3d = make_velocity_face<3>;
  return k;
}

}  // namespace mpm::boundary
