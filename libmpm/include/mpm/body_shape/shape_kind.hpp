#pragma once
/// \file body_shape/shape_kind.hpp
/// The one registry of body shape kinds (`bodies[].shape`): box, disk, sphere, cylinder, polygon, ring, the union,
/// intersection and difference of shapes, a particle file, and what modules register (geometry/: mesh, image). A
/// kind is a scene name, the keys it reads (io::KeySpec, from which its table in docs/scene-reference.md is
/// generated), a parser through the one YAML reader into its own plain description (a `std::any`), its bounding box
/// (the grid check of the body section), a region per dimension (the inside test the lattice fill asks) or a fill of
/// its own (particles that are not on the lattice), and its traits: the dimensions it exists in, whether its volume
/// is known exactly, whether it may be an operand of a union, intersection or difference, whether it gives a
/// conforming CPDI mesh. The core's kinds live one file each in src/body_shape/; the body section, the scene
/// builder, the memory estimate and `mpm particles` read this table, never a kind's name.
///
/// Scene syntax: most kinds are named by `type` (`{type: disk, center: [...], radius: r}`); a kind that is
/// `keyed` is named by its own key instead, whose value is its main datum (`{mesh: part.stl, scale: 1e-3}`,
/// `{union: [shape, shape]}`).

#include <any>
#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mpm/body_shape/lattice_fill.hpp"
#include "mpm/body_shape/region.hpp"
#include "mpm/scene/key_spec.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm {

namespace io {
class YamlReader;
class YamlMap;
struct YamlValue;
}  // namespace io

/// A problem of a shape found while filling it (a file that cannot be used, a shape outside the grid, a threshold
/// that selects nothing). what() is `FILE: problem` (or the problem alone); `key` names the shape's key the problem
/// is at, below `shape` ("particles" for a particle file's rows; empty: the shape itself).
class ShapeError : public std::runtime_error {
 public:
  ShapeError(std::string file, std::string problem, std::string key = "")
      : std::runtime_error(file.empty() ? problem : file + ": " + problem),
        file(std::move(file)),
        problem(std::move(problem)),
        key(std::move(key)) {}
  std::string file;     ///< the file read, empty when the error is not about a file
  std::string problem;  ///< what is wrong
  std::string key;      ///< the key below the shape the error is at, or empty
};

/// Where a shape is being read.
struct ShapeContext {
  int dimension = 0;
  std::string scene_file;   ///< relative file names are taken from its folder
  bool whole_shape = true;  ///< false inside a union, intersection or difference
  /// A shape that makes several bodies (an image's `labels`) appends one entry per body: the suffix of the body's
  /// name (`<name>_<suffix>`) and that body's description. Null where a shape must make one body.
  std::vector<std::pair<std::string, std::any>>* bodies = nullptr;
};

/// What a kind combines with. An empty "not_*" string means it does; otherwise it says why not, for the message.
struct ShapeTraits {
  std::array<bool, 3> dimensions{true, true, true};  ///< exists in 1D, 2D, 3D
  /// Its region knows its volume exactly (closed form, polygon area, mesh volume, pixel sum): `volume: exact` can
  /// scale the lattice particles to it.
  bool exact_volume = false;
  /// `volume` defaults to `exact` (the volume comes with the shape's data: polygon, mesh, image), else `lattice`.
  bool exact_by_default = false;
  /// `domains: conforming` can mesh it (a polygonal boundary in 2D, a closed surface in 3D; geometry/).
  bool conforming_mesh = false;
  /// Its operands are shapes (union, intersection, difference); messages list such kinds last.
  bool combination = false;
  std::string not_operand;  ///< why it cannot be part of a union, intersection or difference
  std::string not_cpdi;     ///< why the cpdi_* shape functions cannot take its particles (they have no domains)
};

/// Reads a shape of the kind from `map` (its `type` key, or its own key, already known). Throws SceneError naming
/// file, line, column and key.
using ShapeParser = std::any (*)(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context);
/// Lower and upper corners (the first `dimension` axes meaningful), m.
using ShapeBoundingBox = std::pair<std::array<double, 3>, std::array<double, 3>>;
/// The bounding box of a parsed description, or nothing when only its file knows it.
using ShapeBoundsOf = std::optional<ShapeBoundingBox> (*)(const std::any& spec, int dimension);
/// The file a description reads (for messages and the memory estimate's cheap bound), or "".
using ShapeFileOf = std::string (*)(const std::any& spec);
/// The region of a description (reads its file, if any; throws ShapeError); repairs go to `warnings`.
template <int Dim>
using ShapeRegionMaker = std::unique_ptr<Region<Dim>> (*)(const std::any& spec, std::vector<std::string>* warnings);
/// The particles of a kind that places its own (not the lattice fill of its region): a particle file, an image's
/// `resolution: pixel`. Returns nothing to use the lattice fill after all. Throws ShapeError.
template <int Dim>
using ShapeFiller = std::optional<ParticleSeeds<Dim>> (*)(const std::any& spec, const GridGeometry<Dim>& grid);

/// How many particles a kind that places its own will make, before they are made (the memory check).
struct OwnParticleCount {
  double count = 0;    ///< 0: not known before the fill (a particle file: as many as its rows)
  bool exact = false;  ///< the count is exact
};
/// The count of a description whose particles are its own, or nothing when it is filled on the lattice.
using ShapeOwnCount = std::optional<OwnParticleCount> (*)(const std::any& spec, int dimension);

struct ShapeKind {
  std::string name;               ///< the value of `type`, or the key of a keyed kind
  std::string noun;               ///< the kind in a sentence: "a disk", "an image", "a particle file"
  std::string description;        ///< one line for the scene reference
  bool keyed = false;             ///< named by its own key (`mesh: FILE`) instead of `type: NAME`
  std::vector<io::KeySpec> keys;  ///< its keys besides `type` (a keyed kind's own key first), for the reference
  ShapeTraits traits;
  ShapeParser parse = nullptr;
  ShapeBoundsOf bounds = nullptr;  ///< null: only the file knows (checked when the body is filled)
  ShapeFileOf file = nullptr;      ///< null: reads no file
  ShapeRegionMaker<1> region_1d = nullptr;
  ShapeRegionMaker<2> region_2d = nullptr;
  ShapeRegionMaker<3> region_3d = nullptr;
  ShapeFiller<1> fill_1d = nullptr;  ///< null: the lattice fill of the region
  ShapeFiller<2> fill_2d = nullptr;
  ShapeFiller<3> fill_3d = nullptr;
  ShapeOwnCount own_count = nullptr;  ///< null: always on the lattice

  template <int Dim>
  ShapeRegionMaker<Dim> region() const {
    if constexpr (Dim == 1) return region_1d;
    if constexpr (Dim == 2) return region_2d;
    if constexpr (Dim == 3) return region_3d;
  }
  template <int Dim>
  ShapeFiller<Dim> filler() const {
    if constexpr (Dim == 1) return fill_1d;
    if constexpr (Dim == 2) return fill_2d;
    if constexpr (Dim == 3) return fill_3d;
  }
};

/// Adds (or replaces) the kind with this name. The core's kinds are registered when the table is first read.
void register_shape_kind(ShapeKind kind);
/// The kind with this name, or nullptr. The pointer stays valid.
const ShapeKind* find_shape_kind(std::string_view name);
/// The registered names, in registration order (the core's first).
std::vector<std::string> shape_kind_names();
/// The kind of a description (std::logic_error for one of an unregistered kind).
const ShapeKind& shape_kind(const ShapeDescription& shape);

/// A description of kind `kind` with the plain description `spec`: for code that makes shapes without a scene.
template <class Spec>
ShapeDescription make_shape(std::string kind, Spec spec) {
  ShapeDescription shape;
  shape.kind = std::move(kind);
  shape.spec = std::move(spec);
  return shape;
}

/// Reads the shape at `value` through the kind it names (see the file comment).
ShapeDescription read_body_shape(const io::YamlReader& reader, const io::YamlValue& value, const ShapeContext& context);
/// The bounding box of a shape, or nothing when only its file knows it.
std::optional<ShapeBoundingBox> shape_bounds(const ShapeDescription& shape, int dimension);
/// The file a shape reads (the first one of a combination's operands), or "".
std::string shape_file(const ShapeDescription& shape);
/// The region of a shape in `Dim` dimensions (std::logic_error when its kind has none there). Throws ShapeError.
template <int Dim>
std::unique_ptr<Region<Dim>> make_shape_region(const ShapeDescription& shape,
                                               std::vector<std::string>* warnings = nullptr);
/// A body's particles from its shape: the kind's own fill, or the lattice fill of its region on `grid` with
/// `particles_per_cell`, the particles sharing the region's exact volume when `exact` (and it knows one), else each
/// with its sub-cell's; `exact` absent: the kind's default (ShapeTraits::exact_by_default). Throws ShapeError for an
/// unusable file, a shape that reaches outside the grid (naming the axis and both spans). Repairs are appended to
/// `warnings`.
template <int Dim>
ParticleSeeds<Dim> fill_shape(const ShapeDescription& shape, const GridGeometry<Dim>& grid,
                              const std::array<int, 3>& particles_per_cell, std::vector<std::string>* warnings,
                              std::optional<bool> exact = std::nullopt);

/// The file name at `value` made relative to the scene file's folder and normalised; fails unless its extension
/// (lower case) is one of `extensions` and the file exists ("unsupported WHAT format", "WHAT file '...' not found").
std::string read_shape_file(const io::YamlReader& reader, const io::YamlValue& value, const std::string& scene_file,
                            const std::vector<std::string>& extensions, std::string_view what);

}  // namespace mpm
