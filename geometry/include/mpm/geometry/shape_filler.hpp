#pragma once
/// \file shape_filler.hpp
/// A body's particles from its scene shape: the region (primitives, polygons, meshes, images and their
/// combinations) filled on the grid lattice, or one particle per pixel for `resolution: pixel` images.

#include <string>
#include <vector>

#include "mpm/geometry/primitive_filler.hpp"

namespace mpm::geometry {

/// Throws GeometryError for an unusable file, for a shape that reaches outside the grid (naming the axis
/// and both spans) and for a shape that gets no particle. Repairs are appended to `warnings`.
template <int Dim>
ParticleSeeds<Dim> fill_shape(const ShapeDescription& shape, const GridGeometry<Dim>& grid,
                              const std::array<int, 3>& particles_per_cell, std::vector<std::string>* warnings);

}  // namespace mpm::geometry
