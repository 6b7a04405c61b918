#include "mpm/geometry/primitive_filler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mpm::geometry {

template <int Dim>
bool contains(const ShapeDescription& s, const Vec<Dim>& x) {
  if (s.type == "box") {
    for (int d = 0; d < Dim; ++d)
      if (x[d] < s.min[d] || x[d] > s.max[d]) return false;
    return true;
  }
  if (s.type == "disk" || s.type == "sphere") {
    Real r2 = 0;
    for (int d = 0; d < Dim; ++d) r2 += (x[d] - s.center[d]) * (x[d] - s.center[d]);
    return r2 <= s.radius * s.radius;
  }
  if (s.type == "cylinder") {
    Real r2 = 0;
    for (int d = 0; d < Dim; ++d) {
      const Real dx = x[d] - s.center[d];
      if (d == s.axis) {
        if (dx < 0 || dx > s.length) return false;
      } else {
        r2 += dx * dx;
      }
    }
    return r2 <= s.radius * s.radius;
  }
  throw std::invalid_argument("unknown shape type '" + s.type + "'");
}

namespace {
/// Axis-aligned bounding box of the shape, per axis.
template <int Dim>
void bounds(const ShapeDescription& s, Vec<Dim>& lo, Vec<Dim>& hi) {
  for (int d = 0; d < Dim; ++d) {
    if (s.type == "box") {
      lo[d] = s.min[d];
      hi[d] = s.max[d];
    } else if (s.type == "cylinder" && d == s.axis) {
      lo[d] = s.center[d];
      hi[d] = s.center[d] + s.length;
    } else {
      lo[d] = s.center[d] - s.radius;
      hi[d] = s.center[d] + s.radius;
    }
  }
}
}  // namespace

template <int Dim>
ParticleSeeds<Dim> fill_primitive(const ShapeDescription& shape, const GridGeometry<Dim>& g,
                                  const std::array<int, 3>& ppc) {
  ParticleSeeds<Dim> seeds;
  Vec<Dim> lo, hi;
  bounds<Dim>(shape, lo, hi);
  std::array<int, 3> first{0, 0, 0}, last{0, 0, 0};  // cell range touching the bounding box
  seeds.volume = g.cell_volume();
  for (int d = 0; d < Dim; ++d) {
    first[d] = std::clamp(static_cast<int>(std::floor((lo[d] - g.origin[d]) * g.inv_h[d])), 0, g.cells(d) - 1);
    last[d] = std::clamp(static_cast<int>(std::floor((hi[d] - g.origin[d]) * g.inv_h[d])), 0, g.cells(d) - 1);
    seeds.volume /= ppc[d];
  }
  std::array<int, 3> cell{}, sub{};
  for (cell[2] = first[2]; cell[2] <= last[2]; ++cell[2])
    for (cell[1] = first[1]; cell[1] <= last[1]; ++cell[1])
      for (cell[0] = first[0]; cell[0] <= last[0]; ++cell[0])
        for (sub[2] = 0; sub[2] < (Dim > 2 ? ppc[2] : 1); ++sub[2])
          for (sub[1] = 0; sub[1] < (Dim > 1 ? ppc[1] : 1); ++sub[1])
            for (sub[0] = 0; sub[0] < ppc[0]; ++sub[0]) {
              Vec<Dim> x;
              for (int d = 0; d < Dim; ++d) x[d] = g.origin[d] + g.h[d] * (cell[d] + (sub[d] + 0.5) / ppc[d]);
              if (contains<Dim>(shape, x)) seeds.positions.push_back(x);
            }
  return seeds;
}

template bool contains<1>(const ShapeDescription&, const Vec<1>&);
template bool contains<2>(const ShapeDescription&, const Vec<2>&);
template bool contains<3>(const ShapeDescription&, const Vec<3>&);
template ParticleSeeds<1> fill_primitive<1>(const ShapeDescription&, const GridGeometry<1>&, const std::array<int, 3>&);
template ParticleSeeds<2> fill_primitive<2>(const ShapeDescription&, const GridGeometry<2>&, const std::array<int, 3>&);
template ParticleSeeds<3> fill_primitive<3>(const ShapeDescription&, const GridGeometry<3>&, const std::array<int, 3>&);

}  // namespace mpm::geometry
