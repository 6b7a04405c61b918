#pragma once
/// \file checkpoint_sink.hpp
/// Where a run's checkpoints go. The run object (run.hpp) decides when one is written (a step the sink says is due,
/// a stop on request, the end of the run) and fills it (the simulation's, the output's, the histories' and the run
/// record's state); the sink keeps the schedule and writes the file. The program's sink writes HDF5 files
/// (`RunCheckpoints`, apps/run_checkpoints.hpp, through checkpoint/), so that the run object needs no file format.

#include <filesystem>

#include "mpm/core/state_archive.hpp"
#include "mpm/core/types.hpp"

namespace mpm {

class CheckpointSink {
 public:
  virtual ~CheckpointSink() = default;
  /// Whether a checkpoint is due after a step that reached `time` (s).
  virtual bool due(double time) const = 0;
  /// Whether the end of the run gets a checkpoint (the scene asks for checkpoints).
  virtual bool at_end() const = 0;
  /// Adds what the sink keeps (its schedule, the run's metadata) to `archive` and writes it as the checkpoint of
  /// `step`; returns the file written, or an empty path when this process writes none (a distributed run's ranks
  /// but 0).
  virtual std::filesystem::path write(StateArchive& archive, Index step, double time) = 0;
};

}  // namespace mpm
