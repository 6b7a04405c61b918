// Regions without CGAL: box, disk/sphere, cylinder (any axis), polygon, union, intersection, difference;
// make_region() dispatches meshes and images to mesh_region.cpp and image_region.cpp.
#include "mpm/geometry/region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mpm/geometry/image_region.hpp"
#include "mpm/geometry/mesh_region.hpp"
#include "mpm/geometry/polygon_region.hpp"

namespace mpm::geometry {

namespace {

template <int Dim>
Vec<Dim> vec(const std::array<double, 3>& a) {
  Vec<Dim> v;
  for (int d = 0; d < Dim; ++d) v[d] = a[d];
  return v;
}

template <int Dim>
class BoxRegion : public Region<Dim> {
 public:
  explicit BoxRegion(const ShapeDescription& s) : box_{vec<Dim>(s.min), vec<Dim>(s.max)} {}
  bool contains(const Vec<Dim>& x) const override {
    return (x.array() >= box_.lo.array()).all() && (x.array() <= box_.hi.array()).all();
  }
  Box<Dim> bounds() const override { return box_; }

 private:
  Box<Dim> box_;
};

/// Disk (2D) or sphere (3D).
template <int Dim>
class BallRegion : public Region<Dim> {
 public:
  explicit BallRegion(const ShapeDescription& s) : centre_(vec<Dim>(s.center)), radius_(s.radius) {}
  bool contains(const Vec<Dim>& x) const override { return (x - centre_).squaredNorm() <= radius_ * radius_; }
  Box<Dim> bounds() const override {
    return {centre_ - Vec<Dim>::Constant(radius_), centre_ + Vec<Dim>::Constant(radius_)};
  }

 private:
  Vec<Dim> centre_;
  Real radius_;
};

/// Circular cylinder from the base centre along a unit direction.
template <int Dim>
class CylinderRegion : public Region<Dim> {
 public:
  explicit CylinderRegion(const ShapeDescription& s)
      : base_(vec<Dim>(s.center)), axis_(vec<Dim>(s.direction).normalized()), radius_(s.radius), length_(s.length) {
    if (s.axis >= 0) axis_ = Vec<Dim>::Unit(s.axis);  // x, y or z
  }
  bool contains(const Vec<Dim>& x) const override {
    const Vec<Dim> r = x - base_;
    const Real t = r.dot(axis_);
    if (t < 0 || t > length_) return false;
    return (r - t * axis_).squaredNorm() <= radius_ * radius_;
  }
  Box<Dim> bounds() const override {
    // The end disks' extents: radius * sqrt(1 - a_d^2) on axis d around the base and the top centre.
    Box<Dim> b;
    const Vec<Dim> top = base_ + length_ * axis_;
    for (int d = 0; d < Dim; ++d) {
      const Real reach = radius_ * std::sqrt(std::max<Real>(0, 1 - axis_[d] * axis_[d]));
      b.lo[d] = std::min(base_[d], top[d]) - reach;
      b.hi[d] = std::max(base_[d], top[d]) + reach;
    }
    return b;
  }

 private:
  Vec<Dim> base_, axis_;
  Real radius_, length_;
};

enum class Combination { union_of, intersection_of, difference_of };

template <int Dim>
class CombinedRegion : public Region<Dim> {
 public:
  CombinedRegion(Combination kind, std::vector<std::unique_ptr<Region<Dim>>> parts)
      : kind_(kind), parts_(std::move(parts)) {
    if (parts_.empty()) throw std::invalid_argument("a union, intersection or difference needs at least one shape");
  }
  bool contains(const Vec<Dim>& x) const override {
    switch (kind_) {
      case Combination::union_of:
        return std::any_of(parts_.begin(), parts_.end(), [&](const auto& p) { return p->contains(x); });
      case Combination::intersection_of:
        return std::all_of(parts_.begin(), parts_.end(), [&](const auto& p) { return p->contains(x); });
      case Combination::difference_of:
        return parts_[0]->contains(x) &&
               std::none_of(parts_.begin() + 1, parts_.end(), [&](const auto& p) { return p->contains(x); });
    }
    return false;
  }
  Box<Dim> bounds() const override {
    Box<Dim> b = parts_[0]->bounds();
    if (kind_ == Combination::difference_of) return b;
    for (std::size_t k = 1; k < parts_.size(); ++k) {
      const Box<Dim> p = parts_[k]->bounds();
      if (kind_ == Combination::union_of) {
        b.lo = b.lo.cwiseMin(p.lo);
        b.hi = b.hi.cwiseMax(p.hi);
      } else {
        b.lo = b.lo.cwiseMax(p.lo);
        b.hi = b.hi.cwiseMin(p.hi);
      }
    }
    return b;
  }

 private:
  Combination kind_;
  std::vector<std::unique_ptr<Region<Dim>>> parts_;
};

/// Even-odd crossing test of a point against the edges of one loop: true when the ray from x towards +x
/// crosses the loop an odd number of times.
bool crosses_odd(const PolygonRegion::Loop& loop, const Vec<2>& x) {
  bool odd = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec<2>& a = loop[i];
    const Vec<2>& b = loop[j];
    if ((a[1] > x[1]) != (b[1] > x[1])) {
      const Real cross_x = a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
      if (x[0] < cross_x) odd = !odd;
    }
  }
  return odd;
}

}  // namespace

Real signed_area(const PolygonRegion::Loop& loop) {
  Real s = 0;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
    s += loop[j][0] * loop[i][1] - loop[i][0] * loop[j][1];
  return s / 2;
}

PolygonRegion::PolygonRegion(std::vector<Loop> loops) : loops_(std::move(loops)) {
  if (loops_.empty()) throw std::invalid_argument("a polygon needs at least one loop");
  bounds_.lo = Vec<2>::Constant(std::numeric_limits<Real>::infinity());
  bounds_.hi = -bounds_.lo;
  for (const auto& loop : loops_) {
    if (loop.size() < 3) throw std::invalid_argument("a polygon loop needs at least 3 corners");
    for (const auto& v : loop) {
      bounds_.lo = bounds_.lo.cwiseMin(v);
      bounds_.hi = bounds_.hi.cwiseMax(v);
    }
  }
  // Even-odd area: a loop nested in an odd number of other loops is a hole (loops do not cross).
  for (std::size_t i = 0; i < loops_.size(); ++i) {
    int depth = 0;
    for (std::size_t j = 0; j < loops_.size(); ++j)
      if (j != i && crosses_odd(loops_[j], loops_[i][0])) ++depth;
    area_ += (depth % 2 == 0 ? 1 : -1) * std::abs(signed_area(loops_[i]));
  }
}

bool PolygonRegion::contains(const Vec<2>& x) const {
  if ((x.array() < bounds_.lo.array()).any() || (x.array() > bounds_.hi.array()).any()) return false;
  bool odd = false;
  for (const auto& loop : loops_) odd ^= crosses_odd(loop, x);
  return odd;
}

std::vector<PolygonRegion::Loop> polygon_loops(const Region<2>& region) {
  if (const auto* polygon = dynamic_cast<const PolygonRegion*>(&region)) return polygon->loops();
  if (const auto* box = dynamic_cast<const BoxRegion<2>*>(&region)) {
    const Box<2> b = box->bounds();
    return {{b.lo, Vec<2>(b.hi[0], b.lo[1]), b.hi, Vec<2>(b.lo[0], b.hi[1])}};
  }
  return {};
}

template <int Dim>
std::unique_ptr<Region<Dim>> make_region(const ShapeDescription& s, std::vector<std::string>* warnings) {
  const std::string& t = s.type;
  if (t == "box") return std::make_unique<BoxRegion<Dim>>(s);
  if (t == "union" || t == "intersection" || t == "difference") {
    std::vector<std::unique_ptr<Region<Dim>>> parts;
    for (const auto& part : s.parts) parts.push_back(make_region<Dim>(part, warnings));
    const Combination kind = t == "union"          ? Combination::union_of
                             : t == "intersection" ? Combination::intersection_of
                                                   : Combination::difference_of;
    return std::make_unique<CombinedRegion<Dim>>(kind, std::move(parts));
  }
  if (t == "image") return make_image_region<Dim>(s);
  if constexpr (Dim == 2) {
    if (t == "disk") return std::make_unique<BallRegion<2>>(s);
    if (t == "polygon") {
      PolygonRegion::Loop loop;
      for (const auto& v : s.vertices) loop.emplace_back(v[0], v[1]);
      return std::make_unique<PolygonRegion>(std::vector<PolygonRegion::Loop>{loop});
    }
    if (t == "mesh") return make_mesh_section(s, warnings);
  }
  if constexpr (Dim == 3) {
    if (t == "sphere") return std::make_unique<BallRegion<3>>(s);
    if (t == "cylinder") return std::make_unique<CylinderRegion<3>>(s);
    if (t == "mesh") return make_mesh_region(s, warnings);
  }
  throw std::invalid_argument("shape type '" + t + "' is not available in " + std::to_string(Dim) + "D");
}

template std::unique_ptr<Region<1>> make_region<1>(const ShapeDescription&, std::vector<std::string>*);
template std::unique_ptr<Region<2>> make_region<2>(const ShapeDescription&, std::vector<std::string>*);
template std::unique_ptr<Region<3>> make_region<3>(const ShapeDescription&, std::vector<std::string>*);

}  // namespace mpm::geometry
