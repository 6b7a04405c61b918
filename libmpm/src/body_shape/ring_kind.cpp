// `type: ring` (docs/scene-reference.md, bodies[].shape): in 2D an annulus (inner_radius <= |x - center| <=
// outer_radius), in 3D a tube: that annulus swept along an axis from the centre of its base. Its area or volume is
// known exactly, pi (R^2 - r^2) (times the length in 3D), so `volume: exact` can give it to the particles.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "kinds.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::shapes {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace ring {

const std::vector<io::KeySpec>& keys() {
  using io::KeyType;
  static const std::vector<io::KeySpec> k = [] {
    std::vector<io::KeySpec> keys{
        {.name = "center",
         .type = KeyType::list,
         .unit = "m",
         .required = true,
         .description = "the centre (3D: of the base)",
         .type_text = "list of `dimension` numbers"},
        {.name = "inner_radius",
         .type = KeyType::number,
         .unit = "m",
         .range = io::Range::above(0),
         .required = true,
         .description = "the radius of the hole",
         .allowed_text = "> 0, below `outer_radius`"},
        {.name = "outer_radius",
         .type = KeyType::number,
         .unit = "m",
         .range = io::Range::above(0),
         .required = true,
         .description = "the outer radius"},
    };
    for (auto a : shape_axis_keys("tube")) {
      a.description = "3D only: " + a.description;
      keys.push_back(std::move(a));
    }
    return keys;
  }();
  return k;
}

std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  std::vector<std::string> allowed = typed_keys(keys());
  if (context.dimension == 2) allowed.resize(4);  // type, center and the radii: no axis in 2D
  map.allow(allowed);
  RingShape ring;
  ring.center = reader.vector(map.required("center"), context.dimension, io::Range::any(), "m");
  const io::YamlValue inner = map.required("inner_radius");
  ring.inner_radius = reader.number(inner, io::Range::above(0), "m");
  ring.outer_radius = reader.number(map.required("outer_radius"), io::Range::above(0), "m");
  if (!(ring.inner_radius < ring.outer_radius))
    reader.fail(inner, fmt::format("the inner radius must be below the outer radius; got inner_radius {:g} m, "
                                   "outer_radius {:g} m",
                                   ring.inner_radius, ring.outer_radius));
  if (context.dimension == 3) ring.axis = read_shape_axis(reader, map);
  return ring;
}

std::optional<ShapeBoundingBox> bounds(const std::any& spec, int dimension) {
  const auto& ring = std::any_cast<const RingShape&>(spec);
  if (dimension == 3) return cylinder_bounds(ring.center, ring.outer_radius, ring.axis);
  ShapeBoundingBox box{{0, 0, 0}, {0, 0, 0}};
  for (int d = 0; d < 2; ++d) {
    box.first[d] = ring.center[d] - ring.outer_radius;
    box.second[d] = ring.center[d] + ring.outer_radius;
  }
  return box;
}

/// An annulus (2D) or a tube (3D), boundary included.
template <int Dim>
class RingRegion : public Region<Dim> {
 public:
  explicit RingRegion(const RingShape& s)
      : base_(to_vec<Dim>(s.center)), inner_(s.inner_radius), outer_(s.outer_radius), length_(s.axis.length) {
    if constexpr (Dim == 3) {
      axis_ = to_vec<3>(s.axis.direction).normalized();
      if (s.axis.axis >= 0) axis_ = Vec<3>::Unit(s.axis.axis);
    }
  }
  bool contains(const Vec<Dim>& x) const override {
    Vec<Dim> r = x - base_;
    if constexpr (Dim == 3) {
      const Real t = r.dot(axis_);
      if (t < 0 || t > length_) return false;
      r -= t * axis_;
    }
    const Real r2 = r.squaredNorm();
    return r2 >= inner_ * inner_ && r2 <= outer_ * outer_;
  }
  Box<Dim> bounds() const override {
    if constexpr (Dim == 2) {
      return {base_ - Vec<2>::Constant(outer_), base_ + Vec<2>::Constant(outer_)};
    } else {
      Box<3> b;
      const Vec<3> top = base_ + length_ * axis_;
      for (int d = 0; d < 3; ++d) {
        const Real reach = outer_ * std::sqrt(std::max<Real>(0, 1 - axis_[d] * axis_[d]));
        b.lo[d] = std::min(base_[d], top[d]) - reach;
        b.hi[d] = std::max(base_[d], top[d]) + reach;
      }
      return b;
    }
  }
  std::optional<Real> exact_volume() const override {
    const Real area = std::numbers::pi * (outer_ * outer_ - inner_ * inner_);
    return Dim == 2 ? area : area * length_;
  }

 private:
  Vec<Dim> base_;
  Vec<3> axis_ = Vec<3>::UnitZ();
  Real inner_, outer_, length_;
};

template <int Dim>
std::unique_ptr<Region<Dim>> region(const std::any& spec, std::vector<std::string>*) {
  return std::make_unique<RingRegion<Dim>>(std::any_cast<const RingShape&>(spec));
}

}  // namespace ring
}  // namespace

ShapeKind ring_kind() {
  using namespace ring;
  ShapeKind k;
  k.name = "ring";
  k.noun = "a ring";
  k.description = "an annulus between two radii (2D); in 3D a tube: the annulus along an axis from its base";
  k.keys = keys();
  k.traits.dimensions = {false, true, true};
  k.traits.exact_volume = true;
  k.parse = parse;
  k.bounds = bounds;
  k.region_2d = region<2>;
  k.region_3d = region<3>;
  return k;
}

}  // namespace mpm::shapes
