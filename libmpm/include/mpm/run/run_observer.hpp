#pragma once
/// \file run_observer.hpp
/// What a front end watches and decides while the run object (run.hpp) steps: the progress line and the stop signals
/// of `mpm run`, the callback and the polling (Ctrl-C) of the Python package, the flight recorder after the guard
/// stopped the run. Every member has a default that does nothing.

#include "mpm/core/stability_error.hpp"
#include "mpm/simulation/simulation.hpp"

namespace mpm {

template <int Dim>
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  /// Asked at the end of every step (its number), before the step's reduction over the ranks of a distributed run:
  /// true on any rank interrupts the run after that step on every rank (a stop signal arrived). The run then writes
  /// a checkpoint and the last frame (RunEnd::interrupted).
  virtual bool interrupt_requested(Index /*step*/) { return false; }
  /// After every step, once its output, checks and checkpoint are done: the progress line, a callback. True stops
  /// the run after this step (RunEnd::stopped; the last frame is written). May throw to end the run at once.
  virtual bool after_step(const Simulation<Dim>& /*sim*/) { return false; }
  /// After the stability guard or the energy sentinel stopped the run and the last good state was written, before
  /// the StabilityError goes on to the caller (the flight recorder replays the failure here).
  virtual void on_stability_error(Simulation<Dim>& /*sim*/, const StabilityReport& /*report*/) {}
};

}  // namespace mpm
