#include "soup_shells.hpp"

#include <limits>
#include <numeric>

namespace mpm::geometry::detail {

std::vector<std::size_t> soup_shells(std::size_t point_count, const std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<std::size_t> parent(point_count);  // union-find over the points, path halving
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& polygon : polygons)
    for (std::size_t k = 1; k < polygon.size(); ++k) {
      const std::size_t a = root(polygon[0]), b = root(polygon[k]);
      if (a != b) parent[b] = a;
    }
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> number(point_count, none), shell(polygons.size(), 0);
  std::size_t shells = 0;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (polygons[f].empty()) continue;
    std::size_t& n = number[root(polygons[f][0])];
    if (n == none) n = shells++;
    shell[f] = n;
  }
  return shell;
}

}  // namespace mpm::geometry::detail
