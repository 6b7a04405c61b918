#pragma once
/// \file communicator.hpp
/// What the engine asks of the other processes of a distributed run (docs/distributed.md §3): the
/// global sums, bounds and flags of a step. The engine and the physics modules see only this interface; MPI lives
/// in the `distributed/` library (MpiCommunicator), built with MPM_WITH_MPI. Every reduction is exact and so
/// independent of the number of ranks and of the order they combine in: sums are ExactSum (the bits of one sum
/// over every rank's terms), bounds are max/min (exact in floating point), flags a logical or.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "mpm/core/exact_sum.hpp"

namespace mpm {

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Every rank's sums merged, the same on every rank: sums[i] becomes the exact sum of all ranks' terms of
  /// sums[i] (ExactSum::merge over ranks).
  virtual void sum(std::span<ExactSum> sums) = 0;
  /// values[i] becomes its maximum (minimum) over the ranks. NaN is not a value here: the guard flags it first.
  virtual void max(std::span<double> values) = 0;
  virtual void min(std::span<double> values) = 0;
  /// True on every rank when `flag` is true on any (the stability guard's roll-back is collective).
  virtual bool any(bool flag) = 0;
  /// values[i] becomes its sum over the ranks (integers: exact in any order).
  virtual void sum(std::span<std::int64_t> values) = 0;

  /// A point-to-point message of a halo exchange, whose size both sides know.
  struct Outgoing {
    int peer;
    std::span<const std::byte> bytes;
  };
  struct Incoming {
    int peer;
    std::span<std::byte> bytes;
  };
  /// Sends every `sends[k].bytes` to its peer and fills every `receives[k].bytes` from its peer; returns when all
  /// have arrived. Two messages between the same pair in one call go in the order given.
  virtual void exchange(std::span<const Outgoing> sends, std::span<const Incoming> receives) = 0;
  /// A message started by start_send or start_receive: in flight until wait() returns. Until then a send's bytes
  /// must stay valid and unchanged, a receive's valid and unread.
  class Transfer {
   public:
    virtual ~Transfer() = default;
    virtual void wait() = 0;
  };
  /// Starts one message of a halo exchange and returns at once, so that the sender and the receiver can compute
  /// while it travels (the overlapped exchange of a scatter, tile_halo.hpp). Messages between the same pair go in
  /// the order they are started, as with exchange(). The default runs exchange() with the one message and returns a
  /// finished transfer: right for a communicator whose exchange does not wait for the peer.
  virtual std::unique_ptr<Transfer> start_send(const Outgoing& message);
  virtual std::unique_ptr<Transfer> start_receive(const Incoming& message);
  /// Every rank gives a buffer for every rank (`out[q]` for rank q, its own included); returns the buffers the
  /// ranks gave this one (`in[q]` from rank q). The migration of particles.
  virtual std::vector<std::vector<std::byte>> all_to_all(std::vector<std::vector<std::byte>> out) = 0;
  /// `bytes` of rank `root`, on every rank.
  virtual void broadcast(std::vector<std::byte>& bytes, int root) = 0;
  virtual void barrier() = 0;
  /// Ends every process of the job with `status`: an internal error on one rank must not leave the others
  /// waiting in a collective.
  [[noreturn]] virtual void abort(int status) = 0;
};

/// One process: every reduction is the identity.
class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void sum(std::span<ExactSum>) override {}
  void max(std::span<double>) override {}
  void min(std::span<double>) override {}
  bool any(bool flag) override { return flag; }
  void sum(std::span<std::int64_t>) override {}
  void exchange(std::span<const Outgoing> sends, std::span<const Incoming> receives) override;
  std::vector<std::vector<std::byte>> all_to_all(std::vector<std::vector<std::byte>> out) override { return out; }
  void broadcast(std::vector<std::byte>&, int) override {}
  void barrier() override {}
  [[noreturn]] void abort(int status) override;
};

}  // namespace mpm
