#pragma once
/// \file frame_reader.hpp
/// One output frame read back through VTK (the file a user opens): the particle positions and every point array,
/// so that a stability case can measure a field of the state a run ended in (the pressure of a locked block, the
/// gap between two bodies).

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace mpm::verification {

struct Frame {
  std::vector<std::array<double, 3>> points;          ///< m, the particle centres
  std::map<std::string, std::vector<double>> arrays;  ///< name -> values, `components` per particle
  std::map<std::string, int> components;
  std::size_t size() const { return points.size(); }
  /// Component `c` of array `name` at particle `i` (throws std::out_of_range for an array the frame lacks).
  double at(const std::string& name, std::size_t i, int c = 0) const {
    return arrays.at(name)[i * static_cast<std::size_t>(components.at(name)) + static_cast<std::size_t>(c)];
  }
};

/// Reads one .vtu file (throws std::runtime_error if VTK cannot).
Frame read_frame(const std::filesystem::path& vtu);
/// The .vtu files of `dir` (not recursively) in the order written (their names carry the frame number).
std::vector<std::filesystem::path> frame_files(const std::filesystem::path& dir);

}  // namespace mpm::verification
