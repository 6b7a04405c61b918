#include "mpm/io/collective_write.hpp"

#include <fmt/format.h>

#include <exception>
#include <stdexcept>
#include <vector>

namespace mpm::io {

void write_collectively(Communicator* comm, const std::string& what, const std::function<void()>& write) {
  if (!comm || comm->size() == 1) {
    write();
    return;
  }
  std::string error;
  bool failed = false;
  try {
    write();
  } catch (const std::exception& e) {
    failed = true;
    error = e.what();
  } catch (...) {
    failed = true;
    error = "unknown exception";
  }
  // The lowest failing rank, or size() when none failed: the flag and the culprit in one reduction.
  std::vector<double> first_failure = {failed ? static_cast<double>(comm->rank()) : static_cast<double>(comm->size())};
  comm->min(first_failure);
  const int culprit = static_cast<int>(first_failure[0]);
  if (culprit == comm->size()) return;
  if (failed) throw std::runtime_error(fmt::format("{} failed on rank {}: {}", what, comm->rank(), error));
  throw std::runtime_error(fmt::format("{} failed on rank {} (its message is in that rank's output); rank {} stops too",
                                       what, culprit, comm->rank()));
}

}  // namespace mpm::io
