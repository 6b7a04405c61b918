// An internal error on one rank ends the whole job: rank 1 aborts while the others wait in a
// barrier; mpirun must end with a non-zero status instead of hanging (ctest's timeout catches a hang).
#include <cstdio>

#include "mpm/distributed/mpi_communicator.hpp"

int main(int argc, char** argv) {
  mpm::distributed::MpiCommunicator world(&argc, &argv);
  if (world.rank() == 1 % world.size()) {
    std::fprintf(stderr, "rank %d: simulated internal error, aborting the job\n", world.rank());
    world.abort(4);
  }
  world.barrier();  // never passed: rank 1 does not arrive
  std::fprintf(stderr, "rank %d: passed a barrier that rank 1 never reached\n", world.rank());
  return 0;
}
