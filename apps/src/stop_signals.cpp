#include "mpm/app/stop_signals.hpp"

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace mpm::app {
namespace {

volatile std::sig_atomic_t stop_signal = 0;
constexpr int handled[] = {SIGINT, SIGTERM, SIGUSR1};
struct sigaction previous[3];

void on_signal(int signal) {
  if (signal == SIGINT && stop_signal != 0) _exit(128 + SIGINT);  // the second Ctrl-C: stop at once
  if (stop_signal == 0) stop_signal = signal;
}

}  // namespace

StopSignals::StopSignals() {
  stop_signal = 0;
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // interrupted reads and writes of the output go on
  for (int k = 0; k < 3; ++k) sigaction(handled[k], &action, &previous[k]);
}

StopSignals::~StopSignals() {
  for (int k = 0; k < 3; ++k) sigaction(handled[k], &previous[k], nullptr);
}

int StopSignals::requested() { return stop_signal; }

void debug_raise_at_step(long long step) {
  static const char* spec = std::getenv("MPM_DEBUG_RAISE_AT_STEP");
  if (!spec) return;
  const char* colon = std::strchr(spec, ':');
  if (!colon || std::atoll(spec) != step) return;
  std::string names = colon + 1;  // NAME or NAME+NAME+...: sent one after the other
  for (std::size_t begin = 0; begin <= names.size();) {
    const std::size_t end = std::min(names.find('+', begin), names.size());
    const std::string name = names.substr(begin, end - begin);
    begin = end + 1;
    const int signal = name == "INT"    ? SIGINT
                       : name == "TERM" ? SIGTERM
                       : name == "USR1" ? SIGUSR1
                       : name == "KILL" ? SIGKILL
                                        : 0;
    if (signal != 0) std::raise(signal);  // to this thread, handled before raise() returns
  }
}

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGUSR1:
      return "SIGUSR1";
    default:
      return "a signal";
  }
}

}  // namespace mpm::app

namespace mpm::app {

void debug_fail_at_step(int rank, long long step) {
  static const char* spec = std::getenv("MPM_DEBUG_FAIL_AT_STEP");
  if (!spec) return;
  const char* colon = std::strchr(spec, ':');
  if (!colon || std::atoi(spec) != rank || std::atoll(colon + 1) != step) return;
  throw std::runtime_error("debug failure of rank " + std::to_string(rank) + " after step " + std::to_string(step) +
                           " (MPM_DEBUG_FAIL_AT_STEP)");
}

}  // namespace mpm::app
