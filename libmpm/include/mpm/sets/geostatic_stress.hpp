#pragma once
/// \file sets/geostatic_stress.hpp
/// A set condition's `initial_stress: geostatic` (docs/theory.md eqs 20.1-20.2): the stress of the set's material
/// at rest under gravity below its free surface. Gravity must point along an axis, the vertical. The set's
/// particles are grouped into the columns of grid cells they lie in (the horizontal cell indices); in each column
/// the free surface is the top of its highest particle (its position plus half the side of the square, or cube, of
/// its volume) and the vertical stress at a particle is the weight of the material above it,
///   sigma_v(z_k) = |g| [rho_0 (z_s - z_0) + sum_{j=1..k} (rho_{j-1} + rho_j) (z_{j-1} - z_j) / 2]   (20.1)
/// over the column's particles from the top down (rho = m / V; exactly rho |g| (z_s - z) in a uniform layer, and
/// layers of different density add up). The horizontal normal stresses (plane strain's out-of-plane one and the
/// axisymmetric hoop stress included) are K0 sigma_v (20.2), K0 the condition's `k0` or each body's model's
/// (MaterialModel::at_rest_coefficient); the shear stresses are zero. Compression is negative.

#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/particles/body.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm {

/// Gives the particles of every set with a geostatic condition their geostatic stress (after mark_particle_sets:
/// the bodies carry their set membership). Throws SceneError at the condition when solver.gravity is zero or not
/// along an axis, or when a body's model gives no K0 and the condition no `k0`.
template <int Dim>
void apply_geostatic_stress(const SceneDescription& scene, std::vector<Body<Dim>>& bodies,
                            const GridGeometry<Dim>& geometry);

}  // namespace mpm
