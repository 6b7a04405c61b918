#pragma once
/// \file image_region.hpp
/// Bodies from images: 2D PNG or PGM pictures and 3D VTK image files (.vti), read with VTK. A threshold
/// (value >= threshold) or a label (value == label) selects the pixels of the body. Pixel (i, j, k) is the
/// box origin + [i, i+1] x [j, j+1] x [k, k+1] times the pixel size, with j counted from the bottom row of
/// the picture as it is displayed (so y points up).

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "mpm/geometry/file_shapes.hpp"
#include "mpm/geometry/primitive_filler.hpp"
#include "mpm/geometry/region.hpp"

namespace mpm::geometry {

/// Values of an image, x fastest, then y (from the bottom), then z.
struct Image {
  int dimension = 2;                       ///< 2 (PNG, PGM) or 3 (.vti)
  std::array<int, 3> size{1, 1, 1};        ///< pixels per axis
  std::array<double, 3> spacing{0, 0, 0};  ///< from a .vti file (0 for pictures), m
  std::array<double, 3> origin{0, 0, 0};   ///< lower corner from a .vti file (its first point minus half a voxel), m
  std::vector<double> values;              ///< grey value (mean of R, G, B for colour pictures; alpha ignored)
};

/// Reads a .png, .pgm or .vti file. Throws GeometryError when the file is missing, of another format,
/// unreadable, or has no pixel.
Image read_image(const std::string& file);

/// The region of the selected pixels. Throws GeometryError when the selection is empty (naming the
/// threshold or label and the range of values in the image) or the image has another dimension.
template <int Dim>
std::unique_ptr<Region<Dim>> make_image_region(const ImageShape& shape);

/// One particle at the centre of every selected pixel, with the pixel's volume (`resolution: pixel`).
template <int Dim>
ParticleSeeds<Dim> fill_image_pixels(const ImageShape& shape);

}  // namespace mpm::geometry
