#pragma once
/// \file flight_recorder.hpp
/// The flight recorder (docs/scene-reference.md, "Files written"; docs/theory.md §7): when the stability guard
/// stops a run (exit 3), OUTPUT/failure/ holds the run replayed from the guard's last snapshot through the
/// failing step, a frame per step (`particles.pvd`, the failing step's frame last), the failing particle per
/// step (`particle.csv`: position, velocity, F, det F, stress, every other field of the particle, dt), the
/// nodes of the cell it started each step in (`nodes.csv`: mass, momentum, force) and `diagnosis.txt` (the
/// check that failed, the nearest documented cause of the hint table, energy_hints.hpp, and the command that
/// reproduces the run). Written into a temporary directory renamed to failure/ at the end: a failure to write
/// leaves no failure/ at all. A distributed run replays on every rank (the steps are collective) and rank 0 writes
/// the same files as one process: the particles gathered in the one-process order, the failing particle's nodes
/// from the rank that held it.

#include <filesystem>
#include <string>
#include <vector>

#include "mpm/core/stability_error.hpp"
#include "mpm/diagnostics/energy_hints.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm::app {

struct FlightRecord {
  std::filesystem::path directory;  ///< OUTPUT/failure
  Index first_step = 0;             ///< the snapshot's step (the first frame)
  Index frames = 0;                 ///< first_step .. the failing step
};

/// Replays `sim` (after it threw StabilityError `report`) into `output_directory`/failure. `fields`: the output
/// fields of the frames; `command`: the command line that reproduces the run. Throws (and leaves no failure/)
/// when a file cannot be written or the replay does not fail where the run did. A collective call in a distributed
/// run (rank 0 writes; the others return the record without writing).
template <int Dim>
FlightRecord record_failure(Simulation<Dim>& sim, const StabilityReport& report, const HintContext& context,
                            const std::filesystem::path& output_directory, const std::vector<std::string>& fields,
                            const std::string& command);

}  // namespace mpm::app
