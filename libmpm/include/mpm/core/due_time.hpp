#pragma once
/// \file due_time.hpp
/// The next time a periodic action (an output frame, a history row, a checkpoint) is due.

#include <cmath>
#include <limits>

#include "mpm/core/types.hpp"

namespace mpm {

/// `next` advanced by whole `interval`s until it is above `time`. Adding the interval one at a time is what the
/// writers did and still do for the usual few turns (their times stay bit for bit); past 1000 turns (an interval far
/// below the step, `output.interval: 5e-324` found by the scene fuzz test, which never ended) the multiple is taken
/// in closed form, and when the interval is too small to move `next` at all, the next representable time is due.
inline Real next_due_time(Real next, Real interval, Real time) {
  if (!(interval > 0)) return next;
  if ((time - next) / interval > 1000) next += (std::floor((time - next) / interval) + 1) * interval;
  for (int turn = 0; next <= time && turn < 1000; ++turn) next += interval;
  if (next <= time) next = std::nextafter(time, std::numeric_limits<Real>::infinity());
  return next;
}

}  // namespace mpm
