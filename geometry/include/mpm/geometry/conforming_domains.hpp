#pragma once
/// \file conforming_domains.hpp
/// CPDI particle domains that follow the body's boundary (review §3.6, §4.3): the shape is meshed with
/// CGAL and every element becomes one particle at its centroid, with the element's volume and its
/// corners as offsets. 2D: a constrained Delaunay triangle mesh of the polygonal boundary (box, polygon,
/// section of a CAD mesh), CPDI-T3. 3D: a Mesh_3 tetrahedral mesh of a closed surface (CAD mesh or box),
/// CPDI-Tet4. Domain volumes sum to the meshed body's volume (2D: exactly the polygon's area).

#include <string>
#include <vector>

#include "mpm/geometry/cpdi_domains.hpp"
#include "mpm/geometry/geometry_error.hpp"

namespace mpm::geometry {

/// Triangles whose longest edges are at most sqrt(2) x `spacing` (a lattice sub-cell splits into two
/// triangles of that diagonal), counter-clockwise corners. Throws GeometryError for a shape that is not
/// polygonal (a disk, an image, a union, ...).
CpdiParticles<2> conforming_triangles(const ShapeDescription& shape, Real spacing, std::vector<std::string>* warnings);

/// Tetrahedra of edge length about `spacing` (cells and surface facets; protected creases get edges of
/// about spacing / 2), right-handed corners. Every edge of the input surface whose faces' normals differ
/// by more than 1 degree is protected as a feature, so the boundary facets lie on the input facets and the
/// volumes sum to the mesh volume (1e-10 relative; a fan of many thin triangles makes more elements). When
/// Mesh_3 fails with that protection it retries with other sizes, then with only the creases sharper than
/// 30 degrees, and a warning gives the volume difference. Throws GeometryError for a shape that is neither
/// a mesh nor a box, or when Mesh_3 fails.
CpdiParticles<3> conforming_tetrahedra(const ShapeDescription& shape, Real spacing, std::vector<std::string>* warnings);

/// The elements of the dimension: conforming_triangles (2D) or conforming_tetrahedra (3D).
template <int Dim>
CpdiParticles<Dim> conforming_cpdi_particles(const ShapeDescription& shape, Real spacing,
                                             std::vector<std::string>* warnings) {
  if constexpr (Dim == 2) {
    return conforming_triangles(shape, spacing, warnings);
  } else if constexpr (Dim == 3) {
    return conforming_tetrahedra(shape, spacing, warnings);
  } else {
    throw GeometryError("", "conforming CPDI domains exist in 2D (cpdi_t3) and 3D (cpdi_tet4) only");
  }
}

}  // namespace mpm::geometry
