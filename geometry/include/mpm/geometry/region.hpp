#pragma once
/// \file region.hpp
/// A region of space that a body is filled from: an inside test and a bounding box, and the exact
/// volume when the region knows it (a CAD mesh, an image). Built once from a scene's shape description;
/// the lattice fill (fill_region, primitive_filler.hpp) asks it about every candidate particle position.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::geometry {

/// Axis-aligned box, m.
template <int Dim>
struct Box {
  Vec<Dim> lo, hi;
};

template <int Dim>
class Region {
 public:
  virtual ~Region() = default;
  /// True when x lies in the region (primitives include their boundary).
  virtual bool contains(const Vec<Dim>& x) const = 0;
  /// Axis-aligned bounding box, m.
  virtual Box<Dim> bounds() const = 0;
  /// The region's volume (m^3; m^2 in 2D) when it is known exactly from the input (mesh volume, selected
  /// pixel area), else nothing. When known, the filler gives the particles volumes that sum to it.
  virtual std::optional<Real> exact_volume() const { return std::nullopt; }
};

/// Builds the region of `shape` (every type of ShapeDescription). Mesh and image files are read here;
/// their problems throw GeometryError; repairs (a mesh turned outside in) are appended to `warnings`.
template <int Dim>
std::unique_ptr<Region<Dim>> make_region(const ShapeDescription& shape, std::vector<std::string>* warnings = nullptr);

}  // namespace mpm::geometry
