#pragma once
/// \file collective_write.hpp
/// A write that succeeds on every rank of a distributed run or fails on every rank: the output of docs/distributed.md
/// §4 (an unwritable directory on any rank: every rank stops with status 1, within the frame).

#include <functional>
#include <string>

#include "mpm/parallel/communicator.hpp"

namespace mpm::io {

/// Runs `write` on this rank, then agrees with the other ranks (one reduction, Communicator::min of the failing
/// ranks): when it threw on any rank, every rank throws std::runtime_error, this rank's with its own message
/// ("`what` failed on rank R: ..."), the others' naming the lowest failing rank. With `comm` null or of one rank,
/// `write` runs alone and its exception passes through unchanged. Every rank must call it at the same point.
void write_collectively(Communicator* comm, const std::string& what, const std::function<void()>& write);

}  // namespace mpm::io
