// The registry of face-condition kinds (mpm/boundary/face_condition_kind.hpp): the core's kinds, then whatever
// modules register; reading a face through its kind and making a scene's GridBoundary.
#include "mpm/boundary/face_condition_kind.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <deque>

#include "kinds.hpp"
#include "mpm/core/kind_table.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "mpm/schemes/scheme.hpp"

namespace mpm {
namespace {

/// The core's kinds, then the modules' (core/kind_table.hpp).
KindTable<FaceConditionKind>& table() {
  static KindTable<FaceConditionKind> t{std::deque<FaceConditionKind>{
      boundary::fixed_kind(), boundary::slip_kind(), boundary::free_kind(), boundary::stop_kind(),
      boundary::prescribed_kind(), boundary::outflow_kind(), boundary::absorbing_kind()}};
  return t;
}

const FaceConditionKind& kind_of(const FaceDescription& face) {
  const FaceConditionKind* kind = find_face_condition_kind(face.kind);
  if (!kind) throw std::logic_error("face condition of unregistered kind '" + face.kind + "'");
  return *kind;
}

}  // namespace

void register_face_condition_kind(FaceConditionKind kind) { table().add(std::move(kind)); }

const FaceConditionKind* find_face_condition_kind(std::string_view name) { return table().find(name); }

std::vector<std::string> face_condition_kind_names() { return table().names(); }

FaceDescription read_face_condition(const io::YamlReader& reader, const io::YamlValue& value, const FaceContext& face) {
  FaceDescription d;
  d.where = reader.location(value.mark);
  if (value.node.IsScalar()) {
    std::vector<std::string> bare;
    for (const auto& name : face_condition_kind_names())
      if (find_face_condition_kind(name)->bare) bare.push_back(name);
    d.kind = reader.choice(value, bare);
  } else if (value.node.IsMap()) {
    const io::YamlMap map = reader.map(value);
    d.kind = "prescribed";  // `{velocity: [...], traction: [...]}` needs no type
    if (const auto type = map.find("type")) d.kind = reader.choice(*type, face_condition_kind_names());
  } else {
    std::vector<std::string> bare;
    for (const auto& name : face_condition_kind_names())
      if (find_face_condition_kind(name)->bare) bare.push_back(name);
    reader.fail(value, fmt::format("expected {}, {{velocity: [...], traction: [...]}} or {{type: KIND, ...}}, got {}",
                                   fmt::join(bare, ", "), io::describe(value.node)));
  }
  d.spec = kind_of(d).parse(reader, value, face);
  return d;
}

FaceTraits face_traits(const FaceDescription& face) { return kind_of(face).traits(face.spec); }

template <int Dim>
GridBoundary<Dim> make_grid_boundary(const GridGeometry<Dim>& g, const std::array<FaceDescription, 6>& faces) {
  std::vector<std::unique_ptr<FaceCondition<Dim>>> conditions;
  for (int f = 0; f < 2 * Dim; ++f) {
    const FaceDescription& face = faces[static_cast<std::size_t>(f)];
    if (auto c = kind_of(face).template maker<Dim>()(face.spec, g, f)) conditions.push_back(std::move(c));
  }
  if (conditions.empty()) return GridBoundary<Dim>();
  return GridBoundary<Dim>(g, std::move(conditions));
}

template <int Dim>
GridBoundary<Dim> make_grid_boundary(const SceneDescription& scene, const GridGeometry<Dim>& g,
                                     const Scheme<Dim>& scheme) {
  for (int f = 0; f < 2 * Dim; ++f) {
    const FaceDescription& face = scene.grid.boundary[static_cast<std::size_t>(f)];
    if (const std::string why = face_traits(face).not_fixed_order; !why.empty() && !scheme.reorders_particles())
      throw SceneError(face.where, std::string("grid.boundary.") + face_names[static_cast<std::size_t>(f)],
                       fmt::format("scheme {}: {}", scheme.name(), why));
  }
  return make_grid_boundary<Dim>(g, scene.grid.boundary);
}

template GridBoundary<1> make_grid_boundary(const GridGeometry<1>&, const std::array<FaceDescription, 6>&);
template GridBoundary<2> make_grid_boundary(const GridGeometry<2>&, const std::array<FaceDescription, 6>&);
template GridBoundary<3> make_grid_boundary(const GridGeometry<3>&, const std::array<FaceDescription, 6>&);
template GridBoundary<1> make_grid_boundary(const SceneDescription&, const GridGeometry<1>&, const Scheme<1>&);
template GridBoundary<2> make_grid_boundary(const SceneDescription&, const GridGeometry<2>&, const Scheme<2>&);
template GridBoundary<3> make_grid_boundary(const SceneDescription&, const GridGeometry<3>&, const Scheme<3>&);

}  // namespace mpm
