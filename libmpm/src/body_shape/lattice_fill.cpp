// The lattice fill (mpm/body_shape/lattice_fill.hpp).
#include "mpm/body_shape/lattice_fill.hpp"

#include <algorithm>
#include <cmath>

namespace mpm {

template <int Dim>
ParticleSeeds<Dim> fill_region(const Region<Dim>& region, const GridGeometry<Dim>& g, const std::array<int, 3>& ppc,
                               bool exact) {
  ParticleSeeds<Dim> seeds;
  const Box<Dim> box = region.bounds();
  std::array<int, 3> first{0, 0, 0}, last{0, 0, 0};  // cell range touching the bounding box
  seeds.sub_cell_volume = g.cell_volume();
  for (int d = 0; d < Dim; ++d) {
    first[d] = std::clamp(static_cast<int>(std::floor((box.lo[d] - g.origin[d]) * g.inv_h[d])), 0, g.cells(d) - 1);
    last[d] = std::clamp(static_cast<int>(std::floor((box.hi[d] - g.origin[d]) * g.inv_h[d])), 0, g.cells(d) - 1);
    seeds.sub_cell_volume /= ppc[d];
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
              if (region.contains(x)) seeds.positions.push_back(x);
            }
  seeds.volume = seeds.sub_cell_volume;
  if (const auto volume = exact ? region.exact_volume() : std::nullopt; volume && !seeds.positions.empty())
    seeds.volume = *volume / static_cast<Real>(seeds.positions.size());
  return seeds;
}

template ParticleSeeds<1> fill_region<1>(const Region<1>&, const GridGeometry<1>&, const std::array<int, 3>&, bool);
template ParticleSeeds<2> fill_region<2>(const Region<2>&, const GridGeometry<2>&, const std::array<int, 3>&, bool);
template ParticleSeeds<3> fill_region<3>(const Region<3>&, const GridGeometry<3>&, const std::array<int, 3>&, bool);

}  // namespace mpm
