#pragma once
/// \file mpi_communicator.hpp
/// The Communicator of a distributed run over MPI (MPM_WITH_MPI, docs/distributed.md §3). Only this
/// library includes mpi.h: the engine and the physics modules call the Communicator interface.

#include <mpi.h>

#include "mpm/parallel/communicator.hpp"

namespace mpm::distributed {

class MpiCommunicator final : public Communicator {
 public:
  /// Initialises MPI unless it already is (then it leaves finalising to whoever did), asking for
  /// MPI_THREAD_FUNNELED: only the main thread communicates, never a TBB worker. Works on a duplicate of
  /// MPI_COMM_WORLD, so that no message of the engine meets one of the caller's.
  MpiCommunicator(int* argc, char*** argv);
  ~MpiCommunicator() override;
  MpiCommunicator(const MpiCommunicator&) = delete;
  MpiCommunicator& operator=(const MpiCommunicator&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  /// The carried digits of every sum added as 64-bit integers (exact, any order), the inf/NaN parts as doubles
  /// (inf + inf, inf + NaN, inf + -inf: the same in any order).
  void sum(std::span<ExactSum> sums) override;
  void max(std::span<double> values) override;
  void min(std::span<double> values) override;
  bool any(bool flag) override;
  void sum(std::span<std::int64_t> values) override;
  void exchange(std::span<const Outgoing> sends, std::span<const Incoming> receives) override;
  /// MPI_Isend / MPI_Irecv; the transfer's wait() is MPI_Wait. A transfer destroyed unfinished (an error path: the
  /// job is about to end) is cancelled if it is a receive and released without waiting.
  std::unique_ptr<Transfer> start_send(const Outgoing& message) override;
  std::unique_ptr<Transfer> start_receive(const Incoming& message) override;
  std::vector<std::vector<std::byte>> all_to_all(std::vector<std::vector<std::byte>> out) override;
  void broadcast(std::vector<std::byte>& bytes, int root) override;
  void barrier() override;
  [[noreturn]] void abort(int status) override;

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
  bool finalize_ = false;
};

}  // namespace mpm::distributed
