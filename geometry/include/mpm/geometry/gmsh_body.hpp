#pragma once
/// \file gmsh_body.hpp
/// Bodies from Gmsh volume meshes (`gmsh: FILE`, file_shapes.hpp): the elements of the body's dimension in the
/// chosen physical groups become particles, one per element at its centroid with its exact volume
/// (element_moments.hpp); the mesh's exact volume, centroid and inertia come with them (the certificate's source).

#include <string>
#include <vector>

#include "mpm/geometry/file_shapes.hpp"
#include "mpm/geometry/mass_properties.hpp"

namespace mpm::geometry {

struct GmshParticles {
  std::vector<Vec<3>> positions;                    ///< element centroids, m (z = 0 in 2D)
  std::vector<Real> volumes;                        ///< element volumes, m^3 (areas in 2D, m^2)
  MassProperties exact;                             ///< of the chosen elements (per unit density)
  Vec<3> lo = Vec<3>::Zero(), hi = Vec<3>::Zero();  ///< bounding box of their nodes, m
};

/// The names of the physical groups of `dimension` in the file (read once per process), in tag order.
std::vector<std::string> gmsh_group_names(const std::string& file, int dimension);

/// The highest dimension of the file's elements that this reader makes particles of (3 or 2). Throws GeometryError.
int gmsh_dimension(const std::string& file);

/// The particles of the chosen elements. Throws GeometryError naming the file and the problem: a group name the file
/// does not define (listing those it does), a group without elements of the dimension, a file without such elements,
/// an element type that is not read, an inverted element.
GmshParticles gmsh_particles(const GmshShape& shape, int dimension);

}  // namespace mpm::geometry
