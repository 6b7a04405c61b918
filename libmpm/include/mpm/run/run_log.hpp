#pragma once
/// \file run_log.hpp
/// Where a run's messages go (run.hpp): its warnings ("warning: ..."; the histories', the step estimate's, the
/// materials' state and the energy sentinel's) and its notes ("checkpoint: ..."), one line at a time, so that every
/// front end prints the same lines. `mpm run` prints them to its log (breaking its progress line first); the Python
/// package to stderr.

#include <string>

namespace mpm {

class RunLog {
 public:
  virtual ~RunLog() = default;
  /// One line of text, without its end of line.
  virtual void line(const std::string& text) = 0;
};

}  // namespace mpm
