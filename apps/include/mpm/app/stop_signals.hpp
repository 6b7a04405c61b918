#pragma once
/// \file stop_signals.hpp
/// How `mpm run` stops on a signal. SIGINT (Ctrl-C), SIGTERM and SIGUSR1 (what batch systems send before
/// the wall time) only set a flag: the run finishes its current step, writes a checkpoint and the last
/// frame, says how to resume, and exits with 128 + the signal number (130, 143, 138). A second SIGINT exits
/// at once (130; the previous checkpoint stays valid).

namespace mpm::app {

/// Installs the handlers for its lifetime (the previous ones are put back by the destructor).
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  /// The signal that asked the run to stop, or 0.
  static int requested();
};

/// Test hook: with MPM_DEBUG_RAISE_AT_STEP=N:NAME (NAME one of INT, TERM, USR1, KILL; or NAME+NAME+... for
/// several in a row) the process sends itself that signal after step N, as if it came from outside
/// (tests/apps/test_restart.cpp).
void debug_raise_at_step(long long step);

/// Hidden debug option of distributed runs (issue 18 §4): with MPM_DEBUG_FAIL_AT_STEP=R:S in the environment, rank R
/// throws an internal error after step S, which must end the whole job (MPI_Abort), never leave it hanging.
void debug_fail_at_step(int rank, long long step);

/// "SIGTERM" for 15, ...
const char* signal_name(int signal);

}  // namespace mpm::app
