// `type: cylinder` (3D; docs/scene-reference.md, bodies[].shape): a circular cylinder from the centre of its base
// along an axis (x, y, z or any direction), whose volume is known exactly (pi r^2 L).
#include <cmath>
#include <numbers>

#include "kinds.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::shapes {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace cylinder {

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k = [] {
    std::vector<io::KeySpec> keys{
        {.name = "center",
         .type = KeyType::list,
         .unit = "m",
         .required = true,
         .description = "the centre of the base",
         .type_text = "list of 3 numbers"},
        {.name = "radius",
         .type = KeyType::number,
         .unit = "m",
         .range = io::Range::above(0),
         .required = true,
         .description = "the radius"},
    };
    for (auto& a : shape_axis_keys("cylinder")) keys.push_back(std::move(a));
    return keys;
  }();
  return k;
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  map.allow(typed_keys(keys()));
  CylinderShape c;
  c.center = reader.vector(map.required("center"), context.dimension, io::Range::any(), "m");
  c.radius = reader.number(map.required("radius"), io::Range::above(0), "m");
  c.axis = read_shape_axis(reader, map);
  return c;
}

std::optional<ShapeBoundingBox> bounds(const std::any& spec, int) {
  const auto& c = std::any_cast<const CylinderShape&>(spec);
  return cylinder_bounds(c.center, c.radius, c.axis);
}

/// A circular cylinder from the base centre along a unit direction, boundary included.
class CylinderRegion : public Region<3> {
 public:
  explicit CylinderRegion(const CylinderShape& s)
      : base_(to_vec<3>(s.center)),
        axis_(to_vec<3>(s.axis.direction).normalized()),
        radius_(s.radius),
        length_(s.axis.length) {
    if (s.axis.axis >= 0) axis_ = Vec<3>::Unit(s.axis.axis);  // x, y or z
  }
  bool contains(const Vec<3>& x) const override {
    const Vec<3> r = x - base_;
    const Real t = r.dot(axis_);
    if (t < 0 || t > length_) return false;
    return (r - t * axis_).squaredNorm() <= radius_ * radius_;
  }
  Box<3> bounds() const override {
    // The end disks' extents: radius * sqrt(1 - a_d^2) on axis d around the base and the top centre.
    Box<3> b;
    const Vec<3> top = base_ + length_ * axis_;
    for (int d = 0; d < 3; ++d) {
      const Real reach = radius_ * std::sqrt(std::max<Real>(0, 1 - axis_[d] * axis_[d]));
      b.lo[d] = std::min(base_[d], top[d]) - reach;
      b.hi[d] = std::max(base_[d], top[d]) + reach;
    }
    return b;
  }
  std::optional<Real> exact_volume() const override { return std::numbers::pi * radius_ * radius_ * length_; }

 private:
  Vec<3> base_, axis_;
  Real radius_, length_;
};

std::unique_ptr<Region<3>> region(const std::any& spec, std::vector<std::string>*) {
  return std::make_unique<CylinderRegion>(std::any_cast<const CylinderShape&>(spec));
}

}  // namespace cylinder
}  // namespace

ShapeKind cylinder_kind() {
  using namespace cylinder;
  ShapeKind k;
  k.name = "cylinder";
  k.noun = "a cylinder";
  k.description = "a circular cylinder from the centre of its base along its axis";
  k.keys = keys();
  k.traits.dimensions = {false, false, true};
  k.traits.exact_volume = true;
  k.parse = parse;
  k.bounds = bounds;
  k.region_3d = region;
  return k;
}

}  // namespace mpm::shapes
