// `type: box` (1D, 2D, 3D; docs/scene-reference.md, bodies[].shape): an axis-aligned box from its corners. Its
// volume is known exactly; `domains: conforming` meshes it in 2D and 3D.
#include <fmt/format.h>

#include "kinds.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::shapes {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace box {

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k{
      {.name = "min",
       .type = KeyType::list,
       .unit = "m",
       .required = true,
       .description = "the lower corner",
       .type_text = "list of `dimension` numbers"},
      {.name = "max",
       .type = KeyType::list,
       .unit = "m",
       .required = true,
       .description = "the upper corner, above `min` on every axis",
       .type_text = "list of `dimension` numbers"},
  };
  return k;
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  map.allow(typed_keys(keys()));
  BoxShape box;
  box.min = reader.vector(map.required("min"), context.dimension, io::Range::any(), "m");
  const io::YamlValue max = map.required("max");
  box.max = reader.vector(max, context.dimension, io::Range::any(), "m");
  for (int d = 0; d < context.dimension; ++d)
    if (!(box.min[d] < box.max[d]))
      reader.fail(max, fmt::format("max must exceed min on every axis; on axis {}: min {} m, max {} m", axis_names[d],
                                   box.min[d], box.max[d]));
  return box;
}

std::optional<ShapeBoundingBox> bounds(const std::any& spec, int) {
  const auto& box = std::any_cast<const BoxShape&>(spec);
  return ShapeBoundingBox{box.min, box.max};
}

template <int Dim>
std::unique_ptr<Region<Dim>> region(const std::any& spec, std::vector<std::string>*) {
  const auto& box = std::any_cast<const BoxShape&>(spec);
  return std::make_unique<BoxRegion<Dim>>(Box<Dim>{to_vec<Dim>(box.min), to_vec<Dim>(box.max)});
}

}  // namespace box
}  // namespace

ShapeKind box_kind() {
  using namespace box;
  ShapeKind k;
  k.name = "box";
  k.noun = "a box";
  k.description = "an axis-aligned box";
  k.keys = keys();
  k.traits.exact_volume = true;
  k.traits.conforming_mesh = true;
  k.parse = parse;
  k.bounds = bounds;
  k.region_1d = region<1>;
  k.region_2d = region<2>;
  k.region_3d = region<3>;
  return k;
}

}  // namespace mpm::shapes
