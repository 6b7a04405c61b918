#pragma once
// The end of an MPI GoogleTest program's main: one rank prints the report, every rank's verdict counts (the exit
// status is 1 on every rank when a test failed on any), so that mpirun's status is the verdict of all ranks.
#include <gtest/gtest.h>

#include <cstdio>

#include "mpm/parallel/communicator.hpp"

namespace mpm::test {

inline int run_on_every_rank(Communicator& communicator) {
  if (communicator.rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const bool failed = RUN_ALL_TESTS() != 0;
  const bool any_failed = communicator.any(failed);
  if (failed) std::fprintf(stderr, "rank %d of %d: a test failed\n", communicator.rank(), communicator.size());
  return any_failed ? 1 : 0;
}

}  // namespace mpm::test
