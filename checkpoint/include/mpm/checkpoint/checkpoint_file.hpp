#pragma once
/// \file checkpoint_file.hpp
/// A run's state (StateArchive, libmpm/state_archive.hpp) as an HDF5 file: one dataset per entry, at the
/// entry's path ("bodies/disk/stress" is the (n, 4) float64 dataset `stress` in the group `bodies/disk`),
/// text as a fixed-length string, each dataset with an attribute `checksum` (checksum.hpp) of its bytes.
/// h5py reads it as `h5py.File(f)["bodies/disk/stress"][...]`; `h5dump -H` lists it. HDF5 is used only
/// here: no header of this folder includes it.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/core/state_archive.hpp"

namespace mpm::checkpoint {

/// A file that is no readable checkpoint: missing, empty, not HDF5, truncated, or with a dataset whose bytes
/// do not match its checksum. what() names the file (and the dataset).
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `archive` to `path` atomically: into a hidden temporary file beside it, flushed to the disk
/// (fsync), then renamed onto `path`, so that a run killed while writing leaves `path` as it was (the
/// previous checkpoint stays valid). Throws std::runtime_error naming the file when it cannot be written.
/// `halfway`, when set, is called once half the datasets are written and flushed: the test seam of a run killed
/// while writing (`mpm run --test-kill-in-checkpoint N`, tests/apps/test_restart.cpp).
void write_checkpoint(const std::filesystem::path& path, const StateArchive& archive,
                      const std::function<void()>& halfway = {});

/// Reads a checkpoint and checks every dataset against its checksum. Throws CheckpointError.
StateArchive read_checkpoint(const std::filesystem::path& path);

/// The checkpoint files in `directory` (checkpoint_*.h5), newest (highest step) first; no temporaries.
std::vector<std::filesystem::path> checkpoint_files(const std::filesystem::path& directory);

/// The file name of the checkpoint of step `step`: checkpoint_STEP.h5 (step with 9 digits).
std::string checkpoint_name(long long step);

}  // namespace mpm::checkpoint
