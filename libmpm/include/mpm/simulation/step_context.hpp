#pragma once
/// \file step_context.hpp
/// Everything one time step reads and writes, handed to the scheme and to the modules' phases.

#include <atomic>
#include <utility>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/grid/node_runs.hpp"
#include "mpm/particles/body.hpp"
#include "mpm/simulation/step_profile.hpp"

namespace mpm {

template <int Dim>
class ModuleHooks;
template <int Dim>
class GridBoundary;
class ActiveTiles;
class Communicator;

/// Settings of the transfers that do not change during a run.
template <int Dim>
struct TransferSettings {
  Real flip_fraction = 1;               ///< alpha of eq. 2.53
  Real mass_cutoff = 0;                 ///< kg: nodes lighter than this get zero velocity (eq. 2.63)
  Vec<Dim> gravity = Vec<Dim>::Zero();  ///< m/s^2
  /// alpha of the local non-viscous damping of the momentum update (eq. 2.74), in [0, 1); 0: undamped
  Real damping = 0;
};

template <int Dim>
struct StepContext {
  StepContext(Grid<Dim>& grid_, std::vector<Body<Dim>>& bodies_, const TransferSettings<Dim>& settings_,
              const GridBoundary<Dim>& boundary_, ModuleHooks<Dim>& hooks_)
      : grid(grid_), bodies(bodies_), settings(settings_), boundary(boundary_), hooks(hooks_) {}

  Grid<Dim>& grid;
  std::vector<Body<Dim>>& bodies;
  const TransferSettings<Dim>& settings;
  /// The conditions on the grid's faces (boundary/grid_boundary.hpp), a module of the step that also answers the
  /// position updates (walls, the guard's box) and the energy sentinel (their work).
  const GridBoundary<Dim>& boundary;
  ModuleHooks<Dim>& hooks;
  Real time = 0;   ///< s, at the start of the step
  Real dt = 0;     ///< s
  Index step = 0;  ///< number of the step being taken (1 for the first)
  /// Set by any kernel that sees a non-finite value, det F <= 0 or a particle outside the grid; the
  /// simulation then finds and names the culprit (the kernels only raise the flag, which costs nothing).
  std::atomic<bool> guard_tripped{false};
  WaveSpeedBound<Dim> wave_speed;  ///< gathered by the stress update, for the next CFL time step
  /// Phase timings (step_profile.hpp) when the run is profiled; null otherwise, and then the kernels'
  /// PhaseTimers read no clock.
  StepProfile* profile = nullptr;
  /// A distributed run's other ranks (Simulation::distribute), null in one process: a module that sums over
  /// particles or nodes reduces through it (owned nodes only: `owned_nodes`).
  Communicator* comm = nullptr;
  /// The nodes this rank owns (TileHalo::owned_nodes): every node in one process.
  NodeMask owned_nodes{};
  /// The nodes the grid kernels reset and update (node_runs.hpp): in one process the nodes the particles of this
  /// step's and the previous step's tiles reach (set when the scheme bins the particles, from `active_tiles`), in a
  /// distributed run the nodes the rank holds (TileHalo::held_nodes); every node until then, and for schemes that do
  /// not bin (TLMPM, implicit).
  NodeRuns active_nodes{};
  /// One process: the occupied tiles kept from step to step (Simulation's; null: a dense grid, every node).
  ActiveTiles* active_tiles = nullptr;
};

}  // namespace mpm
