#include "mpm/parallel/communicator.hpp"

#include <cstdlib>
#include <stdexcept>

namespace mpm {

void SerialCommunicator::exchange(std::span<const Outgoing> sends, std::span<const Incoming> receives) {
  if (!sends.empty() || !receives.empty())
    throw std::logic_error("SerialCommunicator::exchange: one process has no peer to exchange with");
}

namespace {
struct FinishedTransfer final : Communicator::Transfer {
  void wait() override {}
};
}  // namespace

std::unique_ptr<Communicator::Transfer> Communicator::start_send(const Outgoing& message) {
  exchange(std::span<const Outgoing>(&message, 1), {});
  return std::make_unique<FinishedTransfer>();
}

std::unique_ptr<Communicator::Transfer> Communicator::start_receive(const Incoming& message) {
  exchange({}, std::span<const Incoming>(&message, 1));
  return std::make_unique<FinishedTransfer>();
}

void SerialCommunicator::abort(int status) { std::exit(status); }

}  // namespace mpm
