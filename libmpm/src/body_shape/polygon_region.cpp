// Polygonal 2D regions (mpm/body_shape/polygon_region.hpp): even-odd inside test, area with holes, boundary loops.
#include "mpm/body_shape/polygon_region.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mpm {
namespace {

/// Even-odd crossing test of a point against the edges of one loop: true when the ray from x towards +x crosses the
/// loop an odd number of times.
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

}  // namespace mpm
