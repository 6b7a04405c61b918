#pragma once
/// \file rank_report.hpp
/// `mpm check SCENE --ranks N`: what a distributed run of the scene on N ranks would hold: the tiles of
/// the scatter, each rank's box of them as `mpirun` deals them (bisect_tiles, tile_halo.hpp, docs/distributed.md
/// §5.1), its particles, cost and messages, the largest rank count that gives every rank particles, and the halo
/// bytes per step (every rank's HaloPlan, the count the MPI tests check against the bytes sent).
/// Any build prints it (it needs no MPI); more ranks than tiles is refused.

#include <ostream>
#include <stdexcept>

#include "mpm/scene/scene.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm::app {

/// More ranks than the grid has tiles (exit status 2; the message names both counts and the option).
struct RankCountError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The report goes to `out`, its warnings (a scheme that runs in one process only, ranks that would start without
/// particles) to `log`.
template <int Dim>
void rank_report(const SceneDescription& scene, const Simulation<Dim>& sim, int ranks, std::ostream& out,
                 std::ostream& log);

}  // namespace mpm::app
