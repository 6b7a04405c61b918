// `type: disk` (2D) and `type: sphere` (3D) (docs/scene-reference.md, bodies[].shape): a ball from its centre and
// radius, whose area or volume is known exactly (pi r^2, 4/3 pi r^3).
#include <cmath>
#include <numbers>

#include "kinds.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::shapes {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace ball {

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k{
      {.name = "center",
       .type = KeyType::list,
       .unit = "m",
       .required = true,
       .description = "the centre",
       .type_text = "list of `dimension` numbers"},
      {.name = "radius",
       .type = KeyType::number,
       .unit = "m",
       .range = io::Range::above(0),
       .required = true,
       .description = "the radius"},
  };
  return k;
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  map.allow(typed_keys(keys()));
  BallShape ball;
  ball.center = reader.vector(map.required("center"), context.dimension, io::Range::any(), "m");
  ball.radius = reader.number(map.required("radius"), io::Range::above(0), "m");
  return ball;
}

std::optional<ShapeBoundingBox> bounds(const std::any& spec, int dimension) {
  const auto& ball = std::any_cast<const BallShape&>(spec);
  ShapeBoundingBox box{{0, 0, 0}, {0, 0, 0}};
  for (int d = 0; d < dimension; ++d) {
    box.first[d] = ball.center[d] - ball.radius;
    box.second[d] = ball.center[d] + ball.radius;
  }
  return box;
}

/// Disk (2D) or sphere (3D), boundary included.
template <int Dim>
class BallRegion : public Region<Dim> {
 public:
  explicit BallRegion(const BallShape& s) : centre_(to_vec<Dim>(s.center)), radius_(s.radius) {}
  bool contains(const Vec<Dim>& x) const override { return (x - centre_).squaredNorm() <= radius_ * radius_; }
  Box<Dim> bounds() const override {
    return {centre_ - Vec<Dim>::Constant(radius_), centre_ + Vec<Dim>::Constant(radius_)};
  }
  std::optional<Real> exact_volume() const override {
    if constexpr (Dim == 2) return std::numbers::pi * radius_ * radius_;
    return 4.0 / 3.0 * std::numbers::pi * radius_ * radius_ * radius_;
  }

 private:
  Vec<Dim> centre_;
  Real radius_;
};

template <int Dim>
std::unique_ptr<Region<Dim>> region(const std::any& spec, std::vector<std::string>*) {
  return std::make_unique<BallRegion<Dim>>(std::any_cast<const BallShape&>(spec));
}

ShapeKind ball_kind(const char* name, int dimension) {
  ShapeKind k;
  k.name = name;
  k.noun = std::string("a ") + name;
  k.description = dimension == 2 ? "a disk from its centre and radius" : "a sphere from its centre and radius";
  k.keys = keys();
  k.traits.dimensions = {false, dimension == 2, dimension == 3};
  k.traits.exact_volume = true;
  k.parse = parse;
  k.bounds = bounds;
  if (dimension == 2) k.region_2d = region<2>;
  if (dimension == 3) k.region_3d = region<3>;
  return k;
}

}  // namespace ball
}  // namespace

ShapeKind disk_kind() { return ball::ball_kind("disk", 2); }
ShapeKind sphere_kind() { return ball::ball_kind("sphere", 3); }

}  // namespace mpm::shapes
