#include "mpm/grid/tile_grid.hpp"

#include <algorithm>

#include "mpm/grid/tile_binning.hpp"

namespace mpm {

std::pair<int, int> TileGrid::reach(int d, int c) const {
  return {std::max(0, c * tile_cells[d] - reach_below),
          std::min(nodes[d] - 1, (c + 1) * tile_cells[d] - 1 + reach_above)};
}

template <int Dim>
TileGrid make_tile_grid(const GridGeometry<Dim>& g, int slab_cells, int below, int above) {
  TileGrid t;
  t.dim = Dim;
  for (int d = 0; d < Dim; ++d) {
    t.tile_cells[d] = d == Dim - 1 ? slab_cells : tile_width(slab_cells);
    t.cells[d] = g.cells(d);
    t.nodes[d] = g.nodes[d];
    t.tiles[d] = (t.cells[d] + t.tile_cells[d] - 1) / t.tile_cells[d];
  }
  t.reach_below = below;
  t.reach_above = above;
  return t;
}
template TileGrid make_tile_grid<1>(const GridGeometry<1>&, int, int, int);
template TileGrid make_tile_grid<2>(const GridGeometry<2>&, int, int, int);
template TileGrid make_tile_grid<3>(const GridGeometry<3>&, int, int, int);

}  // namespace mpm
