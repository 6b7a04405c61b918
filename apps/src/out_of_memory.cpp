#include "mpm/app/out_of_memory.hpp"

#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <new>
#include <stdexcept>

#include "mpm/app/memory_budget.hpp"

namespace mpm::app {
namespace {

[[noreturn]] void on_terminate() {
  std::string message = "terminated without an exception";
  if (const auto e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::bad_alloc&) {
      message = out_of_memory_message();
    } catch (const std::exception& x) {
      message = std::string("internal error: ") + x.what();
    } catch (...) {
      message = "internal error: an unknown exception";
    }
  }
  message = "error: " + message + "\n";
  // write(2): the streams may be in any state when a thread dies.
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message.data(), message.size());
  std::_Exit(1);
}

}  // namespace

std::string out_of_memory_message() {
  return "out of memory (std::bad_alloc): the run asked for more memory than the machine gave it; " +
         format_bytes(available_memory().bytes) +
         " is available now. The scene's estimate, which `mpm check` prints, was within the memory available when "
         "the scene was built: another process may have taken memory since, or the estimate missed a module's data. "
         "Use fewer particles per cell (bodies[].particles_per_cell) or a larger grid.cell_size.";
}

void install_terminate_handler() { std::set_terminate(on_terminate); }

}  // namespace mpm::app
