#pragma once
/// \file body_shape/polygon_region.hpp
/// A 2D region bounded by closed polygonal loops (a scene polygon, or the section of a CAD mesh by a plane). Inside
/// is decided by the even-odd rule, so a loop inside another loop is a hole.

#include <vector>

#include "mpm/body_shape/region.hpp"

namespace mpm {

class PolygonRegion : public Region<2> {
 public:
  using Loop = std::vector<Vec<2>>;  ///< corners, m; the last corner joins the first
  /// Throws std::invalid_argument when there is no loop or a loop has fewer than 3 corners.
  explicit PolygonRegion(std::vector<Loop> loops);
  bool contains(const Vec<2>& x) const override;
  Box<2> bounds() const override { return bounds_; }
  /// The area inside (loops that are holes subtracted), m^2.
  std::optional<Real> exact_volume() const override { return area_; }
  const std::vector<Loop>& loops() const { return loops_; }

 private:
  std::vector<Loop> loops_;
  Box<2> bounds_;
  Real area_ = 0;
};

/// Signed area of one loop by the shoelace formula (positive counter-clockwise), m^2.
Real signed_area(const PolygonRegion::Loop& loop);

/// The boundary loops of a polygonal 2D region (a BoxRegion or a PolygonRegion), or an empty list when the region is
/// not polygonal (a disk, a union, an image).
std::vector<PolygonRegion::Loop> polygon_loops(const Region<2>& region);

}  // namespace mpm
