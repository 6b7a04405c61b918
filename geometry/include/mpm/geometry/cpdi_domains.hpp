#pragma once
/// \file cpdi_domains.hpp
/// CPDI particle elements from the filler's sub-cells (review §3.6, Alg. 5 needs each particle as a small
/// element): a sub-cell becomes one segment (1D) or quadrilateral (2D), two triangles (2D), or six
/// tetrahedra (3D, Kuhn's split along the main diagonal, the same in every sub-cell so that neighbouring
/// elements share faces). Each element is a particle at its centroid with the element's volume.

#include <vector>

#include "mpm/geometry/primitive_filler.hpp"
#include "mpm/shape/cpdi_elements.hpp"

namespace mpm::geometry {

template <int Dim>
struct CpdiParticles {
  std::vector<Vec<Dim>> positions;      ///< element centroids, m
  std::vector<Real> volumes;            ///< element volumes, m^3 (per unit out-of-plane size)
  std::vector<CornerSet<Dim>> offsets;  ///< corners minus centroid, m (unused corners zero)
};

/// Splits every sub-cell of `seeds` (size `spacing` per axis) into elements of `corners` corners:
/// 2 (segment, 1D), 4 (quadrilateral, 2D), 3 (triangle, 2D) or 4 (tetrahedron, 3D). Corners are
/// counter-clockwise in 2D and right-handed in 3D (positive volume).
template <int Dim>
CpdiParticles<Dim> cpdi_particles(const ParticleSeeds<Dim>& seeds, const Vec<Dim>& spacing, int corners);

}  // namespace mpm::geometry
