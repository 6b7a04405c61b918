#pragma once
/// \file element_moments.hpp
/// The exact volume, first and second moments of the first-order elements of a volume mesh (gmsh_mesh.hpp): in 3D
/// the tetrahedron (closed form), hexahedron (trilinear map, 3 x 3 x 3 Gauss points: exact, the integrands are of
/// degree 4 per axis at most) and prism (6-point degree-4 triangle rule x 3 Gauss points: exact); in 2D the triangle
/// (closed form) and quadrangle (bilinear map, 3 x 3 Gauss points), in the plane z = 0 (their z is ignored; the
/// volume is the area). One particle per element sits at the element's centroid with its volume.

#include "mpm/geometry/gmsh_mesh.hpp"
#include "mpm/geometry/mass_properties.hpp"

namespace mpm::geometry {

/// Moments of element `e` of `mesh` about `origin` (subtracted from the nodes), for a body of `dimension` 2 or 3.
/// Throws GeometryError naming the file, the element and its line: a type that is not one of the above (second
/// order elements, pyramids), an inverted or degenerate element (its Jacobian changes sign or vanishes).
RawMoments element_moments(const GmshMesh& mesh, const GmshElement& e, int dimension, const Vec<3>& origin);

}  // namespace mpm::geometry
