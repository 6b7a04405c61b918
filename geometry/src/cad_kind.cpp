// `cad: FILE` (3D; docs/scene-reference.md, bodies[].shape): solids of a STEP, IGES or BREP file read with
// OpenCASCADE (cad_region.cpp, occt/), chosen by part name or index, tessellated and filled like a closed mesh;
// `parts` makes one body per part. The file is read while the scene is (once per process), so that a part name the
// file does not carry is reported at its line. Without MPM_WITH_OCCT the key is refused naming the option.
#include <fmt/format.h>

#include <algorithm>

#include "cad_model.hpp"
#include "mpm/geometry/cad_region.hpp"
#include "mpm/geometry/geometry_error.hpp"
#include "mpm/scene/yaml_reader.hpp"
#include "shape_kinds.hpp"

namespace mpm::geometry {
namespace {
namespace cad {  // named: the library compiles in unity batches (cmake/unity_libraries.cmake)

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k{
      {.name = "cad",
       .type = KeyType::name,
       .required = true,
       .description = "a B-rep file: STEP (`.step`, `.stp`; AP203, AP214, AP242), IGES (`.iges`, `.igs`) or "
                      "OpenCASCADE `.brep`, relative to the scene file's folder; read with OpenCASCADE (build option "
                      "`MPM_WITH_OCCT`). STEP and IGES give their length unit (a part in mm comes in metres); a "
                      "`.brep` has none and is read in metres"},
      {.name = "part",
       .type = KeyType::list,
       .absent = "all solids (with `solid` absent)",
       .description = "the solids of the parts with this name (the product or label names an assembly carries)",
       .type_text = "name, or list of names"},
      {.name = "solid",
       .type = KeyType::list,
       .absent = "all solids (with `part` absent)",
       .description = "solids by index, 0-based in the order of the file's assembly tree (`mpm particles FILE` "
                      "lists them)",
       .type_text = "integer, or list of integers"},
      {.name = "parts",
       .type = KeyType::list,
       .absent = "one body",
       .description = "one body per named part, named `<name>_<part>`, with the body's other keys (whole shape only)",
       .type_text = "list of names"},
      {.name = "tolerance",
       .type = KeyType::number,
       .unit = "m",
       .range = io::Range::above(0),
       .absent = "1e-4 x the solid's bounding-box diagonal",
       .description = "the largest distance between the tessellation and the solid's surface (chordal deviation); "
                      "keep it well below the particle spacing"},
      {.name = "angular_tolerance",
       .type = KeyType::number,
       .unit = "degrees",
       .range = io::Range::open(0, 90),
       .default_value = 20.0,
       .description = "the largest angle between the normals of neighbouring facets on a curved face"},
      {.name = "scale",
       .type = KeyType::number,
       .unit = "-",
       .range = io::Range::above(0),
       .default_value = 1.0,
       .description = "factor on the coordinates after the file's unit is converted to metres, applied first"},
      {.name = "rotation",
       .type = KeyType::list,
       .unit = "degrees",
       .absent = "none",
       .description = "angles about x, then y, then z, applied after the scale",
       .type_text = "list of 3 numbers"},
      {.name = "translation",
       .type = KeyType::list,
       .unit = "m",
       .absent = "none",
       .description = "added last",
       .type_text = "list of 3 numbers"},
  };
  return k;
}

/// A name or a list of names (`part`), or integers (`solid`): the items of a scalar or a list.
std::vector<io::YamlValue> items_of(const io::YamlReader& reader, const io::YamlValue& value, std::string_view what) {
  if (value.node.IsSequence()) {
    auto items = reader.list(value, std::nullopt, what);
    if (items.empty()) reader.fail(value, fmt::format("expected at least one of the {}", what));
    return items;
  }
  return {value};
}

/// Checks the choice against the file now, so that a wrong name is reported at its line.
void check_choice(const io::YamlReader& reader, const io::YamlValue& at, const CadShape& cad) {
  try {
    chosen_cad_solids(cad);
  } catch (const GeometryError& e) {
    reader.fail(at, e.what());
  }
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  const io::YamlValue file = *map.find("cad");
  if (context.dimension != 3) reader.fail(file, "CAD bodies (STEP, IGES, BREP) are available in 3D");
  map.allow({"cad", "part", "solid", "parts", "tolerance", "angular_tolerance", "scale", "rotation", "translation"});
  CadShape cad;
  cad.file = read_shape_file(reader, file, context.scene_file, {".step", ".stp", ".iges", ".igs", ".brep"}, "CAD");
  if (const std::string& why = detail::cad_unavailable(); !why.empty()) reader.fail(file, why);
  try {
    detail::cad_solids(cad.file);  // read now: an unreadable file is reported at the key
  } catch (const GeometryError& e) {
    reader.fail(file, e.what());
  }
  if (const auto tolerance = map.find("tolerance")) cad.tolerance = reader.number(*tolerance, io::Range::above(0), "m");
  if (const auto angle = map.find("angular_tolerance"))
    cad.angular_tolerance = reader.number(*angle, io::Range::open(0, 90), "degrees");
  if (const auto scale = map.find("scale")) cad.scale = reader.number(*scale, io::Range::above(0), "");
  if (const auto rotation = map.find("rotation"))
    cad.rotation = reader.vector(*rotation, 3, io::Range::any(), "degrees");
  if (const auto translation = map.find("translation"))
    cad.translation = reader.vector(*translation, 3, io::Range::any(), "m");
  if (const auto part = map.find("part")) {
    for (const auto& item : items_of(reader, *part, "part names")) {
      CadShape one = cad;
      one.parts = {reader.name(item)};
      check_choice(reader, item, one);
      cad.parts.push_back(one.parts.front());
    }
  }
  if (const auto solid = map.find("solid")) {
    for (const auto& item : items_of(reader, *solid, "solid indices")) {
      CadShape one = cad;
      one.solids = {static_cast<std::size_t>(reader.integer(item, 0))};
      check_choice(reader, item, one);
      cad.solids.push_back(one.solids.front());
    }
  }
  if (const auto parts = map.find("parts")) {
    if (map.find("part") || map.find("solid"))
      reader.fail(*parts, "give parts (one body each) or part/solid, not both");
    if (!context.bodies || !context.whole_shape)
      reader.fail(*parts, "parts (one body per part) needs the CAD file to be the whole shape of the body; use part");
    const auto items = reader.list(*parts, std::nullopt, "part names");
    if (items.empty()) reader.fail(*parts, "expected at least one part name");
    std::vector<std::string> names;
    for (const auto& item : items) {
      CadShape one = cad;
      one.parts = {reader.name(item)};
      if (std::find(names.begin(), names.end(), one.parts.front()) != names.end())
        reader.fail(item, fmt::format("part '{}' is listed twice", one.parts.front()));
      check_choice(reader, item, one);
      names.push_back(one.parts.front());
      context.bodies->emplace_back(one.parts.front(), std::move(one));
    }
  }
  return cad;
}

std::string file_of(const std::any& spec) { return std::any_cast<const CadShape&>(spec).file; }

std::unique_ptr<Region<3>> solid(const std::any& spec, std::vector<std::string>* warnings) {
  return make_cad_region(std::any_cast<const CadShape&>(spec), warnings);
}

}  // namespace cad
}  // namespace

ShapeKind cad_kind() {
  using namespace cad;
  ShapeKind k;
  k.name = "cad";
  k.noun = "a CAD file";
  k.description = "solids of a STEP, IGES or BREP file (OpenCASCADE), tessellated and filled like a closed mesh";
  k.keyed = true;
  k.keys = keys();
  k.traits.dimensions = {false, false, true};
  k.traits.exact_volume = true;
  k.traits.exact_by_default = true;
  k.traits.not_cpdi = "";
  k.parse = parse;
  k.file = file_of;
  k.region_3d = solid;
  return k;
}

}  // namespace mpm::geometry
