#include "mpm/distributed/mpi_communicator.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace mpm::distributed {

MpiCommunicator::MpiCommunicator(int* argc, char*** argv) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    finalize_ = true;
    if (provided < MPI_THREAD_FUNNELED) {
      MPI_Finalize();
      throw std::runtime_error("the MPI library does not allow threads (MPI_THREAD_FUNNELED); mpm's ranks use TBB");
    }
  }
  MPI_Comm_dup(MPI_COMM_WORLD, &comm_);
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

MpiCommunicator::~MpiCommunicator() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (finalised) return;
  MPI_Comm_free(&comm_);
  if (finalize_) MPI_Finalize();
}

void MpiCommunicator::sum(std::span<ExactSum> sums) {
  if (sums.empty()) return;
  constexpr int digits = ExactSum::digits;
  std::vector<std::int64_t> words(sums.size() * digits);
  std::vector<double> special(sums.size());
  for (std::size_t i = 0; i < sums.size(); ++i) {
    const ExactSum::Digits d = sums[i].carried_digits();
    std::copy(d.begin(), d.end(), words.begin() + static_cast<std::ptrdiff_t>(i * digits));
    special[i] = sums[i].special();
  }
  MPI_Allreduce(MPI_IN_PLACE, words.data(), static_cast<int>(words.size()), MPI_INT64_T, MPI_SUM, comm_);
  MPI_Allreduce(MPI_IN_PLACE, special.data(), static_cast<int>(special.size()), MPI_DOUBLE, MPI_SUM, comm_);
  for (std::size_t i = 0; i < sums.size(); ++i) {
    ExactSum::Digits d;
    std::copy(words.begin() + static_cast<std::ptrdiff_t>(i * digits),
              words.begin() + static_cast<std::ptrdiff_t>((i + 1) * digits), d.begin());
    sums[i] = ExactSum::from_digits(d, special[i]);
  }
}

void MpiCommunicator::max(std::span<double> values) {
  if (!values.empty())
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX, comm_);
}

void MpiCommunicator::min(std::span<double> values) {
  if (!values.empty())
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MIN, comm_);
}

bool MpiCommunicator::any(bool flag) {
  int local = flag ? 1 : 0, global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_LOR, comm_);
  return global != 0;
}

void MpiCommunicator::sum(std::span<std::int64_t> values) {
  if (!values.empty())
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT64_T, MPI_SUM, comm_);
}

namespace {
// Halo messages carry this tag; the migration's all-to-all uses collectives, so no tag can meet another's message.
constexpr int halo_tag = 18;
int message_size(std::size_t bytes) {
  if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("a message of more than 2^31 bytes (split the grid into more tiles)");
  return static_cast<int>(bytes);
}
}  // namespace

void MpiCommunicator::exchange(std::span<const Outgoing> sends, std::span<const Incoming> receives) {
  std::vector<MPI_Request> requests(sends.size() + receives.size(), MPI_REQUEST_NULL);
  std::size_t k = 0;
  for (const Incoming& in : receives)
    MPI_Irecv(in.bytes.data(), message_size(in.bytes.size()), MPI_BYTE, in.peer, halo_tag, comm_, &requests[k++]);
  for (const Outgoing& out : sends)
    MPI_Isend(out.bytes.data(), message_size(out.bytes.size()), MPI_BYTE, out.peer, halo_tag, comm_, &requests[k++]);
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

namespace {
class MpiTransfer final : public Communicator::Transfer {
 public:
  explicit MpiTransfer(bool receive) : receive_(receive) {}
  MpiTransfer(const MpiTransfer&) = delete;
  MpiTransfer& operator=(const MpiTransfer&) = delete;
  ~MpiTransfer() override {
    if (request_ == MPI_REQUEST_NULL) return;
    if (receive_) MPI_Cancel(&request_);
    MPI_Request_free(&request_);
  }
  void wait() override { MPI_Wait(&request_, MPI_STATUS_IGNORE); }
  MPI_Request* request() { return &request_; }

 private:
  MPI_Request request_ = MPI_REQUEST_NULL;
  bool receive_;
};
}  // namespace

std::unique_ptr<Communicator::Transfer> MpiCommunicator::start_send(const Outgoing& message) {
  auto t = std::make_unique<MpiTransfer>(false);
  MPI_Isend(message.bytes.data(), message_size(message.bytes.size()), MPI_BYTE, message.peer, halo_tag, comm_,
            t->request());
  return t;
}

std::unique_ptr<Communicator::Transfer> MpiCommunicator::start_receive(const Incoming& message) {
  auto t = std::make_unique<MpiTransfer>(true);
  MPI_Irecv(message.bytes.data(), message_size(message.bytes.size()), MPI_BYTE, message.peer, halo_tag, comm_,
            t->request());
  return t;
}

std::vector<std::vector<std::byte>> MpiCommunicator::all_to_all(std::vector<std::vector<std::byte>> out) {
  const auto n = static_cast<std::size_t>(size_);
  if (out.size() != n) throw std::invalid_argument("all_to_all: one buffer per rank");
  std::vector<long long> send_count(n), receive_count(n);
  for (std::size_t q = 0; q < n; ++q) send_count[q] = static_cast<long long>(out[q].size());
  MPI_Alltoall(send_count.data(), 1, MPI_LONG_LONG, receive_count.data(), 1, MPI_LONG_LONG, comm_);
  std::vector<std::vector<std::byte>> in(n);
  std::vector<MPI_Request> requests;
  requests.reserve(2 * n);
  for (std::size_t q = 0; q < n; ++q) {
    in[q].resize(static_cast<std::size_t>(receive_count[q]));
    if (in[q].empty()) continue;
    requests.emplace_back();
    MPI_Irecv(in[q].data(), message_size(in[q].size()), MPI_BYTE, static_cast<int>(q), halo_tag + 1, comm_,
              &requests.back());
  }
  for (std::size_t q = 0; q < n; ++q) {
    if (out[q].empty()) continue;
    requests.emplace_back();
    MPI_Isend(out[q].data(), message_size(out[q].size()), MPI_BYTE, static_cast<int>(q), halo_tag + 1, comm_,
              &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  return in;
}

void MpiCommunicator::broadcast(std::vector<std::byte>& bytes, int root) {
  long long size = static_cast<long long>(bytes.size());
  MPI_Bcast(&size, 1, MPI_LONG_LONG, root, comm_);
  bytes.resize(static_cast<std::size_t>(size));
  if (size > 0) MPI_Bcast(bytes.data(), message_size(bytes.size()), MPI_BYTE, root, comm_);
}

void MpiCommunicator::barrier() { MPI_Barrier(comm_); }

void MpiCommunicator::abort(int status) {
  MPI_Abort(comm_, status);
  std::abort();  // MPI_Abort does not return; the attribute needs the proof
}

}  // namespace mpm::distributed
