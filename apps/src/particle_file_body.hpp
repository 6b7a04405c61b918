#pragma once
// A body seeded from a particle file (`shape: {particles: FILE}`, docs/scene-reference.md): the particles'
// positions and volumes, and, when the file has them, their velocity, stress, mass and id. The deformation
// gradient starts at I: the file is the initial state of the run.

#include <optional>
#include <vector>

#include "mpm/particles/body.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::app {

template <int Dim>
struct SeedParticles {
  std::vector<Vec<Dim>> positions;
  std::vector<Real> volumes;  ///< m^3 (per unit out-of-plane size in 2D)
  std::optional<std::vector<VecU<Dim>>> velocity;
  std::optional<std::vector<SymTensor<Dim>>> stress;
  std::optional<std::vector<Real>> mass;
  std::optional<std::vector<std::uint32_t>> id;
};

/// The particles of body `index` from its file. Throws SceneError naming the file (and the row) for a file
/// that cannot be read, a missing `volume`, a volume or mass that is not positive, a particle outside the
/// grid, ids that are not distinct whole numbers, or no particle of the selected `body`.
template <int Dim>
SeedParticles<Dim> read_seed_particles(const BodyDescription& bd, int index, const GridGeometry<Dim>& grid);

/// Sets what the file gave besides positions and volumes on the body's particles (added in the file's order).
template <int Dim>
void apply_seed_state(Body<Dim>& body, const SeedParticles<Dim>& seed);

}  // namespace mpm::app
