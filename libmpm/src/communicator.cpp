#include "mpm/communicator.hpp"

#include <cstdlib>

namespace mpm {

void SerialCommunicator::abort(int status) { std::exit(status); }

}  // namespace mpm
