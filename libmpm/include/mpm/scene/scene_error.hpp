#pragma once
/// \file scene_error.hpp
/// The one exception type of scene loading: a message that points at the offending place of the scene
/// file, formatted like a compiler diagnostic so that editors can jump to it.

#include <stdexcept>
#include <string>

#include "mpm/scene/scene.hpp"

namespace mpm {

/// An invalid scene: YAML syntax error, unknown or missing key, wrong type, nonphysical value, ...
///
/// what() is `FILE:LINE:COLUMN: KEY: message` (1-based line and column). Parts that are unknown are
/// left out: without a location it is `FILE: KEY: message`, without a key `FILE:LINE:COLUMN: message`,
/// and without either (e.g. the file cannot be opened) `FILE: message`.
class SceneError : public std::runtime_error {
 public:
  /// \param where   file and 1-based position (line 0 = no position)
  /// \param key     dotted path of the offending key, e.g. `bodies[1].shape.radius` (may be empty)
  /// \param message what is wrong, without the location prefix
  SceneError(SourceLocation where, std::string key, std::string message);

  SourceLocation where;  ///< where in the scene file
  std::string key;       ///< dotted key path, empty when the error is not about one key
  std::string message;   ///< the bare message (what() without the `FILE:LINE:COLUMN: KEY: ` prefix)

  /// The what() text for these parts.
  static std::string format(const SourceLocation& where, const std::string& key, const std::string& message);
};

}  // namespace mpm
