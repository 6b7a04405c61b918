#include "mpm/geometry/shape_filler.hpp"

#include <fmt/format.h>

#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/image_region.hpp"

namespace mpm::geometry {

namespace {

/// The file a shape reads, for messages (the first one in a combination), or "".
std::string file_of(const ShapeDescription& s) {
  if (!s.file.empty()) return s.file;
  for (const auto& part : s.parts)
    if (auto f = file_of(part); !f.empty()) return f;
  return "";
}

}  // namespace

template <int Dim>
ParticleSeeds<Dim> fill_shape(const ShapeDescription& shape, const GridGeometry<Dim>& grid,
                              const std::array<int, 3>& particles_per_cell, std::vector<std::string>* warnings) {
  const auto region = make_region<Dim>(shape, warnings);
  const Box<Dim> box = region->bounds();
  const Vec<Dim> upper = grid.upper();
  constexpr const char* axis_names[3] = {"x", "y", "z"};
  for (int d = 0; d < Dim; ++d) {
    const Real tolerance = 1e-9 * (upper[d] - grid.origin[d]);
    const bool clipped_at_axis = d == 0 && grid.coordinates == Coordinates::axisymmetric;  // r < 0 is not filled
    if ((box.lo[d] < grid.origin[d] - tolerance && !clipped_at_axis) || box.hi[d] > upper[d] + tolerance)
      throw GeometryError(file_of(shape),
                          fmt::format("lies outside the grid: on axis {} it spans [{:.6g}, {:.6g}] m, the grid "
                                      "[{:.6g}, {:.6g}] m",
                                      axis_names[d], box.lo[d], box.hi[d], grid.origin[d], upper[d]));
  }
  if (shape.type == "image" && shape.pixel_particles) return fill_image_pixels<Dim>(shape);
  return fill_region<Dim>(*region, grid, particles_per_cell);
}

template ParticleSeeds<1> fill_shape<1>(const ShapeDescription&, const GridGeometry<1>&, const std::array<int, 3>&,
                                        std::vector<std::string>*);
template ParticleSeeds<2> fill_shape<2>(const ShapeDescription&, const GridGeometry<2>&, const std::array<int, 3>&,
                                        std::vector<std::string>*);
template ParticleSeeds<3> fill_shape<3>(const ShapeDescription&, const GridGeometry<3>&, const std::array<int, 3>&,
                                        std::vector<std::string>*);

}  // namespace mpm::geometry
