#pragma once
/// \file body.hpp
/// A body: a particle set with one material.

#include <memory>
#include <string>

#include "mpm/grid/tile_binning.hpp"
#include "mpm/materials/material.hpp"

namespace mpm {

template <int Dim>
struct Body {
  static constexpr int dimension = Dim;
  std::string name;
  int index = 0;  ///< position in the scene's body list (output field `body`)
  ParticleSet<Dim> particles;
  std::shared_ptr<Material<Dim>> material;  ///< stateless: shared by snapshots
  bool stretched_domain = false;            ///< the particle domain follows diag F (cpGIMP), for output
  int domain_corners = 0;  ///< CPDI: corners per particle domain (2 segment, 3 triangle, 4 quad or tetrahedron)
  TileBins bins;           ///< rebuilt every step by the scheme
  /// Scratch: velocity gradients of all particles, used only when a module runs between the
  /// grid-to-particle transfer and the stress update (otherwise a per-block buffer is enough).
  std::vector<MatU<Dim>> velocity_gradient;
  /// Multi-field MPM (review §5.1): when set, this body's transfers use these nodal arrays instead of the shared
  /// grid (its own mass, momentum, force and velocities), and a module reconciles the fields where they meet
  /// (contact/ sets it and owns the arrays). Null: the body maps to the shared grid.
  Grid<Dim>* separate_grid = nullptr;
};

}  // namespace mpm
