#pragma once
/// \file boundary/face_condition_kind.hpp
/// The one registry of face-condition kinds (`grid.boundary.FACE`): free, stop, fixed, slip, prescribed
/// (`{velocity: [...], traction: [...]}`), outflow, absorbing (dashpots, with a ground motion), and any a module
/// registers. A kind is a scene name, the keys it reads (for the scene reference), a parser through the one YAML
/// reader (io/yaml_reader.hpp, so its errors read like every other section's), its traits (what it combines with),
/// and a maker per dimension of its FaceCondition (face_condition.hpp), which does the work at the stages of the
/// step. The core's kinds live one file each in src/boundary/; the grid section's reader, the builder, the scheme
/// and module checks (implicit, contact, TLMPM) and the reaction history read this table, never a kind's name.
///
/// Scene syntax: a face is either a kind's bare name (`y_max: outflow`, for kinds that take no required key) or a
/// map whose `type` names the kind (`y_max: {type: outflow, margin: 0.01}`); a map without `type` is `prescribed`,
/// so `{velocity: [0, free]}` reads as it always has.

#include <any>
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mpm/boundary/grid_boundary.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm {

namespace io {
class YamlReader;
struct YamlValue;
}  // namespace io
template <int Dim>
class Scheme;

/// Where a face condition is being read.
struct FaceContext {
  int dimension = 0;
  int face = 0;                           ///< the order of face_names
  std::array<double, 3> extent{0, 0, 0};  ///< m, the grid box's lengths
};

/// What a face condition combines with, from its kind and its keys (a prescribed velocity of 0 does no work;
/// one of t does). An empty "not_*" string means it combines; otherwise it says why not, for the scene error.
struct FaceTraits {
  bool holds_velocity = false;     ///< holds a nodal velocity component: a reaction history can measure its force
  bool does_work = false;          ///< a moving velocity condition or a traction (the energy sentinel's W)
  bool traction = false;           ///< adds forces to the shared grid field
  bool removes_particles = false;  ///< lets particles out (outflow)
  std::string not_implicit;        ///< why the implicit scheme cannot take it
  std::string not_contact;         ///< why contact (a velocity field per body) cannot take it
  std::string not_fixed_order;     ///< why a scheme whose particles keep their initial order (TLMPM) cannot
};

/// Reads one face's condition; `value` is the bare name (a scalar) or the map (its `type` key already read).
/// Throws SceneError naming file, line, column and key.
using FaceParser = std::any (*)(const io::YamlReader& reader, const io::YamlValue& value, const FaceContext& face);
/// The traits of a parsed condition.
using FaceTraitsOf = FaceTraits (*)(const std::any& spec);
/// The condition of a parsed spec on face `face` of grid `g`, or null for a kind that does nothing on the grid.
template <int Dim>
using FaceMaker = std::unique_ptr<FaceCondition<Dim>> (*)(const std::any& spec, const GridGeometry<Dim>& g, int face);

/// A key of a kind, for the scene reference.
struct FaceKey {
  std::string name;
  std::string unit;
  std::string description;
};

struct FaceConditionKind {
  std::string name;         ///< the bare name and the map's `type`
  std::string description;  ///< one line for the scene reference
  std::vector<FaceKey> keys;
  bool bare = true;  ///< may be written as its bare name
  FaceParser parse = nullptr;
  FaceTraitsOf traits = nullptr;
  FaceMaker<1> make_1d = nullptr;
  FaceMaker<2> make_2d = nullptr;
  FaceMaker<3> make_3d = nullptr;

  template <int Dim>
  FaceMaker<Dim> maker() const {
    if constexpr (Dim == 1) return make_1d;
    if constexpr (Dim == 2) return make_2d;
    if constexpr (Dim == 3) return make_3d;
  }
};

/// Adds (or replaces) the kind with this name. The core's kinds are registered when the table is first read.
void register_face_condition_kind(FaceConditionKind kind);
/// The kind with this name, or nullptr. The pointer stays valid.
const FaceConditionKind* find_face_condition_kind(std::string_view name);
/// The registered names, in registration order (the core's first).
std::vector<std::string> face_condition_kind_names();

/// Reads `grid.boundary.FACE` (a bare name or a map, see the file comment) through the kind it names.
FaceDescription read_face_condition(const io::YamlReader& reader, const io::YamlValue& value, const FaceContext& face);
/// The traits of a scene's face ("free" for a face without a condition).
FaceTraits face_traits(const FaceDescription& face);
/// The conditions of the scene's faces on grid `g` (the first 2 Dim of `faces`).
template <int Dim>
GridBoundary<Dim> make_grid_boundary(const GridGeometry<Dim>& g, const std::array<FaceDescription, 6>& faces);
/// The scene's face conditions for a run with `scheme`: make_grid_boundary, after checking that the scheme can
/// take them (FaceTraits::not_fixed_order for a scheme that keeps its particles in their initial order, TLMPM).
/// Throws SceneError at the face.
template <int Dim>
GridBoundary<Dim> make_grid_boundary(const SceneDescription& scene, const GridGeometry<Dim>& g,
                                     const Scheme<Dim>& scheme);

}  // namespace mpm
