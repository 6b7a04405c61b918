#pragma once
/// \file stop_signals.hpp
/// How `mpm run` stops on a signal. SIGINT (Ctrl-C), SIGTERM and SIGUSR1 (what batch systems send before
/// the wall time) only set a flag: the run finishes its current step, writes a checkpoint and the last
/// frame, says how to resume, and exits with 128 + the signal number (130, 143, 138). A second SIGINT exits
/// at once (130; the previous checkpoint stays valid).
/// And the test seams of the run path, hidden options of `mpm run` (apps/README.md, "Test seams"): a signal the
/// process sends itself after a step, an internal error of one rank after a step.

#include <optional>
#include <string>
#include <vector>

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

/// `mpm run --test-signal-at STEP:NAME` (NAME one of INT, TERM, USR1, KILL; or NAME+NAME+... for several in a
/// row): the process sends itself those signals during step STEP, as if they came from outside
/// (tests/apps/test_restart.cpp).
struct TestSignal {
  long long step = 0;
  std::vector<int> signals;
};
/// The seam of `spec`, or nullopt when it is not STEP:NAME[+NAME...].
std::optional<TestSignal> parse_test_signal(const std::string& spec);
/// Sends the seam's signals when `step` is its step (each handled before this returns).
void raise_test_signal(const TestSignal& seam, long long step);

/// `mpm run --test-fail-at RANK:STEP`: rank RANK of a distributed run throws an internal error after step STEP,
/// which must end the whole job (MPI_Abort), never leave it hanging (tests/apps/test_parallel_launch.cpp).
struct TestFailure {
  int rank = 0;
  long long step = 0;
};
/// The seam of `spec`, or nullopt when it is not RANK:STEP.
std::optional<TestFailure> parse_test_failure(const std::string& spec);
/// Throws std::runtime_error when `rank` and `step` are the seam's.
void fail_for_test(const TestFailure& seam, int rank, long long step);

/// "SIGTERM" for 15, ...
const char* signal_name(int signal);

}  // namespace mpm::app
