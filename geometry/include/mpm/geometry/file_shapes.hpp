#pragma once
/// \file file_shapes.hpp
/// The plain descriptions of geometry's body shape kinds (registered by register_module(), register.hpp): a CAD
/// surface mesh (`mesh: FILE`, mesh_kind.cpp) and an image (`image: FILE`, image_kind.cpp). What their parsers return
/// in ShapeDescription::spec.

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace mpm::geometry {

/// `mesh: FILE` (.stl, .obj, .off, .ply): a closed surface; 2D scenes cut it by the plane z = section.
struct MeshShape {
  std::string file;                            ///< made relative to the working directory
  double scale = 1;                            ///< factor on the file's coordinates (1e-3 for mm), applied first
  std::array<double, 3> rotation{0, 0, 0};     ///< rotation angles about x, then y, then z, degrees
  std::array<double, 3> translation{0, 0, 0};  ///< added last, m
  std::optional<double> section;               ///< 2D: the plane z = section, m
  std::optional<double> weld;         ///< vertices closer than this are merged first, in the file's coordinates
  std::optional<std::string> object;  ///< an OBJ's object (`o NAME`) alone
  std::optional<std::size_t> shell;   ///< the connected shell with this index (0-based, in file order) alone
};

/// `cad: FILE` (.step, .stp, .iges, .igs, .brep; 3D): solids of a B-rep file read with OpenCASCADE (MPM_WITH_OCCT),
/// each tessellated and filled like a closed mesh. No part and no solid named: all the file's solids.
struct CadShape {
  std::string file;                            ///< made relative to the working directory
  std::vector<std::string> parts;              ///< the solids of the parts (assembly names) with these names
  std::vector<std::size_t> solids;             ///< and the solids with these indices (0-based, in file order)
  std::optional<double> tolerance;             ///< chordal deviation of the tessellation, m (absent: 1e-4 x size)
  double angular_tolerance = 20;               ///< angle between neighbouring facets' normals at most, degrees
  double scale = 1;                            ///< factor after the file's unit is converted to metres
  std::array<double, 3> rotation{0, 0, 0};     ///< about x, then y, then z, degrees
  std::array<double, 3> translation{0, 0, 0};  ///< added last, m
};

/// `gmsh: FILE` (.msh, ASCII 2.2 or 4.1; 2D, 3D): one particle per element of the body's dimension, at its centroid
/// with its volume (area in 2D). No group named: all such elements.
struct GmshShape {
  std::string file;                            ///< made relative to the working directory
  std::vector<std::string> groups;             ///< the elements of the physical groups with these names
  double scale = 1;                            ///< factor on the file's coordinates, applied first
  std::array<double, 3> translation{0, 0, 0};  ///< added last, m
};

/// `image: FILE` (.png, .pgm in 2D; .vti in 3D): the selected pixels form the body.
struct ImageShape {
  std::string file;                             ///< made relative to the working directory
  std::array<double, 3> pixel_size{0, 0, 0};    ///< per axis, m (0: the .vti's spacing)
  std::optional<std::array<double, 3>> origin;  ///< lower corner of the image, m
  std::optional<double> threshold;              ///< pixels with value >= threshold form the body
  std::optional<double> label;                  ///< pixels with exactly this value form the body
  bool pixel_particles = false;                 ///< one particle per selected pixel instead of the grid lattice
};

}  // namespace mpm::geometry
