#pragma once
/// \file geometry_error.hpp
/// The exception of geometry input: a mesh or image file that cannot be used (missing, unreadable, open,
/// non-manifold, self-intersecting, empty, a threshold that selects nothing, ...).

#include <stdexcept>
#include <string>

namespace mpm::geometry {

/// what() is `FILE: problem` (or just the problem when no file is involved); `file` and `problem` are
/// also kept apart so that the scene builder can report them at the shape's place in the scene.
class GeometryError : public std::runtime_error {
 public:
  GeometryError(std::string file, std::string problem)
      : std::runtime_error(file.empty() ? problem : file + ": " + problem),
        file(std::move(file)),
        problem(std::move(problem)) {}
  std::string file;     ///< the mesh or image file, empty when the error is not about a file
  std::string problem;  ///< what is wrong
};

}  // namespace mpm::geometry
