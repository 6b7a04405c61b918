#pragma once
/// \file memory_estimate.hpp
/// The memory a scene needs, estimated before anything of its size is allocated, and its refusal when that is
/// more than the machine has (docs/scene-reference.md, "Limits"). Particles: the lattice fill counted on a sample
/// of each body's region (geometry/particle_count.hpp); bytes per particle: an empty prototype of each body with
/// every field a run adds (scene_builder.hpp, prototype_bodies), times 3 (the state, the stability guard's
/// snapshot and the sort's scratch), plus the scheme's own per-particle data (TLMPM's stencil cache); grid: its
/// nodes times the core's bytes per node, doubled for the modules' nodal fields and the scatter's scratch.

#include <cstddef>
#include <string>
#include <vector>

#include "mpm/app/memory_budget.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/scene/scene.hpp"

namespace mpm::app {

/// Copies of the particle state a run holds at once: the state, the guard's snapshot, the sort's gathered copy.
inline constexpr double particle_state_copies = 3;

struct BodyMemory {
  std::string name;
  double particles = 0;                ///< estimated count
  bool exact = false;                  ///< every lattice point was tested (the count is what the fill makes)
  bool sampled = false;                ///< counted on a sample of the region (else: the bounding box's lattice)
  std::size_t bytes_per_particle = 0;  ///< one copy of the state (the prototype's), plus the scheme's per particle
  double bytes() const;                ///< particles x (copies x state + scheme)
  std::size_t state_bytes = 0;         ///< one copy of the particle fields
};

struct MemoryEstimate {
  double nodes = 0;
  std::size_t bytes_per_node = 0;
  std::vector<BodyMemory> bodies;
  double grid_bytes() const { return nodes * static_cast<double>(bytes_per_node); }
  double particles() const;
  double bytes() const;
};

/// The grid's share of the estimate (nodes and bytes per node, no body).
template <int Dim>
MemoryEstimate estimate_grid_memory(const GridGeometry<Dim>& geometry);

/// The whole estimate. With `sample` false, a body's count is the lattice points of its bounding box (of the grid
/// for shapes read from files), an upper bound that costs no inside test; with `sample` true, the sampled count.
template <int Dim>
MemoryEstimate estimate_memory(const SceneDescription& scene, const GridGeometry<Dim>& geometry, bool sample);

/// Throws SceneError when the scene cannot fit in `budget`: at grid.cell_size when the grid alone does not fit
/// (checked first, before any body is prepared), otherwise at the particles_per_cell of the body needing the
/// most, with the estimate and the memory available. Cheap when the scene clearly fits (upper bounds first).
template <int Dim>
void check_memory(const SceneDescription& scene, const GridGeometry<Dim>& geometry, const MemoryBudget& budget);

}  // namespace mpm::app
