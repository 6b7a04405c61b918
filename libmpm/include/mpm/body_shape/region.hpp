#pragma once
/// \file body_shape/region.hpp
/// A region of space that a body is filled from: an inside test, a bounding box, and its volume when the region
/// knows it exactly (a primitive's closed form, a polygon's area, a CAD mesh's volume, an image's selected pixels).
/// A body shape kind (body_shape/shape_kind.hpp) makes one from its description; the lattice fill
/// (body_shape/lattice_fill.hpp) asks it about every candidate particle position.

#include <optional>

#include "mpm/core/types.hpp"

namespace mpm {

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
  /// The region's volume (m^3; m^2 in 2D, m in 1D) when it is known exactly, else nothing. `volume: exact` gives
  /// the particles volumes that sum to it.
  virtual std::optional<Real> exact_volume() const { return std::nullopt; }
};

/// An axis-aligned box (a `box` shape; the conforming meshers recognise it by this type).
template <int Dim>
class BoxRegion : public Region<Dim> {
 public:
  explicit BoxRegion(Box<Dim> box) : box_(box) {}
  bool contains(const Vec<Dim>& x) const override {
    return (x.array() >= box_.lo.array()).all() && (x.array() <= box_.hi.array()).all();
  }
  Box<Dim> bounds() const override { return box_; }
  std::optional<Real> exact_volume() const override { return (box_.hi - box_.lo).prod(); }

 private:
  Box<Dim> box_;
};

}  // namespace mpm
