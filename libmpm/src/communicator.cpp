#include "mpm/communicator.hpp"

#include <cstdlib>
#include <stdexcept>

namespace mpm {

void SerialCommunicator::exchange(std::span<const Outgoing> sends, std::span<const Incoming> receives) {
  if (!sends.empty() || !receives.empty())
    throw std::logic_error("SerialCommunicator::exchange: one process has no peer to exchange with");
}

void SerialCommunicator::abort(int status) { std::exit(status); }

}  // namespace mpm
