#include "mpm/distributed/mpi_communicator.hpp"

#include <cstdint>
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

void MpiCommunicator::barrier() { MPI_Barrier(comm_); }

void MpiCommunicator::abort(int status) {
  MPI_Abort(comm_, status);
  std::abort();  // MPI_Abort does not return; the attribute needs the proof
}

}  // namespace mpm::distributed
