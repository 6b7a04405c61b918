#include "soup_weld.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace mpm::geometry::detail {

namespace {

/// Union-find with path halving: the groups of points to merge.
struct WeldGroups {
  std::vector<std::size_t> parent;
  explicit WeldGroups(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t root(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = root(a), b = root(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the first point of a group is its root
  }
};

using WeldCell = std::array<std::int64_t, 3>;

struct WeldCellHash {
  std::size_t operator()(const WeldCell& c) const {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

std::size_t weld_soup_points(std::vector<Point3>& points, std::vector<std::vector<std::size_t>>& polygons,
                             double tolerance) {
  // Points in cells of the tolerance's size: a point within the tolerance of another lies in one of the 27 cells
  // around it, so each point is compared with the few in those cells only.
  const auto cell_of = [&](const Point3& p) {
    return WeldCell{static_cast<std::int64_t>(std::floor(p.x() / tolerance)),
                    static_cast<std::int64_t>(std::floor(p.y() / tolerance)),
                    static_cast<std::int64_t>(std::floor(p.z() / tolerance))};
  };
  std::unordered_map<WeldCell, std::vector<std::size_t>, WeldCellHash> cells;
  cells.reserve(points.size());
  WeldGroups groups(points.size());
  const double squared = tolerance * tolerance;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const WeldCell c = cell_of(points[i]);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto near = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (near == cells.end()) continue;
          for (const std::size_t j : near->second)
            if (CGAL::squared_distance(points[i], points[j]) < squared) groups.join(i, j);
        }
    cells[c].push_back(i);
  }
  // Each group becomes the mean of its points (the corners' copies scatter about the true corner), numbered in the
  // order of the groups' first points.
  std::vector<std::size_t> index(points.size());
  std::vector<std::array<double, 3>> sums;
  std::vector<double> counts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t r = groups.root(i);
    if (r == i) {
      index[i] = sums.size();
      sums.push_back({0, 0, 0});
      counts.push_back(0);
    } else {
      index[i] = index[r];  // r < i: numbered already
    }
    auto& s = sums[index[i]];
    s[0] += points[i].x(), s[1] += points[i].y(), s[2] += points[i].z();
    counts[index[i]] += 1;
  }
  const std::size_t removed = points.size() - sums.size();
  std::vector<Point3> merged;
  merged.reserve(sums.size());
  for (std::size_t g = 0; g < sums.size(); ++g)
    merged.emplace_back(sums[g][0] / counts[g], sums[g][1] / counts[g], sums[g][2] / counts[g]);
  points = std::move(merged);
  for (auto& polygon : polygons)
    for (auto& v : polygon) v = index[v];
  return removed;
}

}  // namespace mpm::geometry::detail
