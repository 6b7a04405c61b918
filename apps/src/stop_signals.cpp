#include "mpm/app/stop_signals.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <csignal>
#include <stdexcept>
#include <string_view>

namespace mpm::app {
namespace {

volatile std::sig_atomic_t stop_signal = 0;
constexpr int handled[] = {SIGINT, SIGTERM, SIGUSR1};
struct sigaction previous[3];

void on_signal(int signal) {
  if (signal == SIGINT && stop_signal != 0) _exit(128 + SIGINT);  // the second Ctrl-C: stop at once
  if (stop_signal == 0) stop_signal = signal;
}

/// The whole of `text` as a number, or nullopt.
template <class Number>
std::optional<Number> whole_number(std::string_view text) {
  Number n{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return n;
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

std::optional<TestSignal> parse_test_signal(const std::string& spec) {
  const std::size_t colon = spec.find(':');
  if (colon == std::string::npos) return std::nullopt;
  const auto step = whole_number<long long>(std::string_view(spec).substr(0, colon));
  if (!step) return std::nullopt;
  TestSignal seam{*step, {}};
  const std::string names = spec.substr(colon + 1);  // NAME or NAME+NAME+...: sent one after the other
  for (std::size_t begin = 0; begin <= names.size();) {
    const std::size_t end = std::min(names.find('+', begin), names.size());
    const std::string name = names.substr(begin, end - begin);
    begin = end + 1;
    const int signal = name == "INT"    ? SIGINT
                       : name == "TERM" ? SIGTERM
                       : name == "USR1" ? SIGUSR1
                       : name == "KILL" ? SIGKILL
                                        : 0;
    if (signal == 0) return std::nullopt;
    seam.signals.push_back(signal);
  }
  return seam;
}

void raise_test_signal(const TestSignal& seam, long long step) {
  if (step != seam.step) return;
  for (const int signal : seam.signals) std::raise(signal);  // to this thread, handled before raise() returns
}

std::optional<TestFailure> parse_test_failure(const std::string& spec) {
  const std::size_t colon = spec.find(':');
  if (colon == std::string::npos) return std::nullopt;
  const auto rank = whole_number<int>(std::string_view(spec).substr(0, colon));
  const auto step = whole_number<long long>(std::string_view(spec).substr(colon + 1));
  if (!rank || !step) return std::nullopt;
  return TestFailure{*rank, *step};
}

void fail_for_test(const TestFailure& seam, int rank, long long step) {
  if (rank != seam.rank || step != seam.step) return;
  throw std::runtime_error("debug failure of rank " + std::to_string(rank) + " after step " + std::to_string(step) +
                           " (--test-fail-at)");
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
