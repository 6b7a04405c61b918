#include "mpm/geometry/particle_count.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mpm::geometry {
namespace {

/// The lattice indices k (point x_k = origin + h (k + 1/2) / ppc) of one axis that lie in [lo, hi] and in the
/// grid, as [first, last] (empty when last < first). Doubles: an axis can hold more than 2^31 points.
template <int Dim>
std::array<double, 2> axis_range(const Box<Dim>& box, const GridGeometry<Dim>& g, int ppc, int d) {
  const double per_metre = ppc * g.inv_h[d];
  const double total = static_cast<double>(g.cells(d)) * ppc;
  double first = std::ceil((box.lo[d] - g.origin[d]) * per_metre - 0.5);
  double last = std::floor((box.hi[d] - g.origin[d]) * per_metre - 0.5);
  first = std::max(first, 0.0);
  last = std::min(last, total - 1);
  if (!std::isfinite(first) || !std::isfinite(last)) return {0, -1};
  return {first, last};
}

}  // namespace

template <int Dim>
double lattice_points_in(const Box<Dim>& box, const GridGeometry<Dim>& g, const std::array<int, 3>& ppc) {
  double n = 1;
  for (int d = 0; d < Dim; ++d) {
    const auto [first, last] = axis_range(box, g, ppc[d], d);
    n *= std::max(0.0, last - first + 1);
  }
  return n;
}

template <int Dim>
ParticleCount count_particles(const Region<Dim>& region, const GridGeometry<Dim>& g, const std::array<int, 3>& ppc,
                              std::size_t samples) {
  ParticleCount result;
  const Box<Dim> box = region.bounds();
  std::array<std::array<double, 2>, Dim> range{};
  std::array<double, Dim> points{};
  for (int d = 0; d < Dim; ++d) {
    range[d] = axis_range(box, g, ppc[d], d);
    points[d] = std::max(0.0, range[d][1] - range[d][0] + 1);
  }
  result.lattice = std::accumulate(points.begin(), points.end(), 1.0, std::multiplies<>());
  if (result.lattice == 0) {
    result.exact = true;
    return result;
  }
  // Samples per axis: the short axes whole, the others evenly strided, at most `samples` in all.
  std::array<int, Dim> order{};
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return points[a] < points[b]; });
  std::array<double, Dim> taken{};
  double left = static_cast<double>(samples);
  for (int k = 0; k < Dim; ++k) {
    const int d = order[k];
    const double share = std::floor(std::pow(left, 1.0 / (Dim - k)) + 1e-9);
    taken[d] = std::clamp(share, 1.0, points[d]);
    left = std::max(1.0, left / taken[d]);
  }
  result.exact = std::equal(taken.begin(), taken.end(), points.begin());
  std::array<int, 3> n{1, 1, 1}, j{0, 0, 0};
  for (int d = 0; d < Dim; ++d) n[d] = static_cast<int>(taken[d]);
  std::size_t inside = 0;
  for (j[2] = 0; j[2] < n[2]; ++j[2])
    for (j[1] = 0; j[1] < n[1]; ++j[1])
      for (j[0] = 0; j[0] < n[0]; ++j[0]) {
        Vec<Dim> x;
        for (int d = 0; d < Dim; ++d) {
          // The j-th of `taken` points spread over the axis's range (every point when taken == points).
          const double k = range[d][0] + std::floor((j[d] + 0.5) * points[d] / taken[d]);
          x[d] = g.origin[d] + g.h[d] * (k + 0.5) / ppc[d];
        }
        inside += region.contains(x) ? 1 : 0;
        ++result.sampled;
      }
  result.count = result.exact ? static_cast<double>(inside)
                              : result.lattice * static_cast<double>(inside) / static_cast<double>(result.sampled);
  return result;
}

template double lattice_points_in<1>(const Box<1>&, const GridGeometry<1>&, const std::array<int, 3>&);
template double lattice_points_in<2>(const Box<2>&, const GridGeometry<2>&, const std::array<int, 3>&);
template double lattice_points_in<3>(const Box<3>&, const GridGeometry<3>&, const std::array<int, 3>&);
template ParticleCount count_particles<1>(const Region<1>&, const GridGeometry<1>&, const std::array<int, 3>&,
                                          std::size_t);
template ParticleCount count_particles<2>(const Region<2>&, const GridGeometry<2>&, const std::array<int, 3>&,
                                          std::size_t);
template ParticleCount count_particles<3>(const Region<3>&, const GridGeometry<3>&, const std::array<int, 3>&,
                                          std::size_t);

}  // namespace mpm::geometry
