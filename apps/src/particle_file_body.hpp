#pragma once
// A body seeded from a particle file (`shape: {particles: FILE}`, docs/scene-reference.md): the file's particles come
// from its shape kind (libmpm/src/body_shape/particle_file_kind.cpp) with their positions and volumes, and, when the
// file has them, their velocity, stress, mass and id, which are set here. The deformation gradient starts at I: the
// file is the initial state of the run.

#include "mpm/body_shape/lattice_fill.hpp"
#include "mpm/particles/body.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::app {

/// Sets what the shape gave besides positions and volumes (a particle file's velocity, stress, mass, id) on the
/// body's particles (added in the shape's order); nothing for the lattice's.
template <int Dim>
void apply_seed_state(Body<Dim>& body, const ParticleSeeds<Dim>& seed);

}  // namespace mpm::app
