#pragma once
/// \file pvd_collection.hpp
/// ParaView .pvd collection: the list of (time, file) of a time series, opened in ParaView as one
/// animated data set.

#include <cstddef>
#include <filesystem>
#include <utility>
#include <vector>

namespace mpm::io {

/// A ParaView .pvd collection. add() each frame, then write(): the whole .pvd is rewritten
/// atomically each time, so it is valid after every frame, even if the run is killed.
class PvdCollection {
 public:
  /// The collection that write() will write to `pvd_path` (nothing is written yet).
  explicit PvdCollection(std::filesystem::path pvd_path);

  /// Adds a frame. `file` is a path as it would be opened (absolute, or relative to the current
  /// directory, like pvd_path); it is stored relative to the .pvd's directory.
  /// Throws std::invalid_argument if `time` is not finite.
  void add(double time, const std::filesystem::path& file);
  /// Rewrites the .pvd with all frames added so far, atomically.
  void write() const;

  /// Where the .pvd is written.
  const std::filesystem::path& path() const { return path_; }
  /// Number of frames added.
  std::size_t size() const { return frames_.size(); }
  /// The frames added so far: time and file (absolute), as add() takes them (a checkpoint saves them).
  std::vector<std::pair<double, std::filesystem::path>> frames() const;

 private:
  struct Frame {
    double time;
    std::filesystem::path file;  // relative to path_'s directory
  };
  std::filesystem::path path_;
  std::vector<Frame> frames_;
};

}  // namespace mpm::io
