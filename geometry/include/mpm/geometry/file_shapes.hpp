#pragma once
/// \file file_shapes.hpp
/// The plain descriptions of geometry's body shape kinds (registered by register_module(), register.hpp): a CAD
/// surface mesh (`mesh: FILE`, mesh_kind.cpp) and an image (`image: FILE`, image_kind.cpp). What their parsers return
/// in ShapeDescription::spec.

#include <array>
#include <optional>
#include <string>

namespace mpm::geometry {

/// `mesh: FILE` (.stl, .obj, .off, .ply): a closed surface; 2D scenes cut it by the plane z = section.
struct MeshShape {
  std::string file;                            ///< made relative to the working directory
  double scale = 1;                            ///< factor on the file's coordinates (1e-3 for mm), applied first
  std::array<double, 3> rotation{0, 0, 0};     ///< rotation angles about x, then y, then z, degrees
  std::array<double, 3> translation{0, 0, 0};  ///< added last, m
  std::optional<double> section;               ///< 2D: the plane z = section, m
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
