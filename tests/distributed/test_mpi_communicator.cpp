// The MPI communicator (distributed/): started by ctest under `mpirun -np K` (K = 1..4). Every rank
// takes its share of one list of terms (term i on rank i % K); the reductions must give, on every rank, the bits
// of the serial result over the whole list. The main below initialises MPI and fails the process when any rank
// failed, so that mpirun's exit status is the verdict of all ranks.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "mpm/distributed/mpi_communicator.hpp"
#include "run_on_every_rank.hpp"

namespace {

mpm::distributed::MpiCommunicator* world = nullptr;

/// Terms whose plain floating-point sum depends on their order: magnitudes from 1e-300 to 1e300, both signs,
/// large terms that cancel, and subnormals.
std::vector<double> awkward_terms(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0), exponent(-300.0, 300.0);
  std::vector<double> terms;
  for (int i = 0; i < count; ++i) {
    const double sign = (rng() & 1) ? 1.0 : -1.0;
    switch (i % 4) {
      case 0:
        terms.push_back(sign * mantissa(rng) * std::pow(10.0, exponent(rng)));
        break;
      case 1:
        terms.push_back(sign * mantissa(rng));
        break;
      case 2:  // cancels the previous term but its last bits
        terms.push_back(-terms.back() * (1 + 1e-15));
        break;
      default:
        terms.push_back(sign * 4.9e-324 * static_cast<double>(rng() % 1000));
    }
  }
  return terms;
}

TEST(MpiCommunicator, ExactSumsOverRanksEqualTheSerialSumBitForBit) {
  const int rank = world->rank(), size = world->size();
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const std::vector<double> terms = awkward_terms(1001, seed);
    mpm::ExactSum serial;
    for (const double t : terms) serial.add(t);
    std::vector<mpm::ExactSum> sums(2);
    for (std::size_t i = rank; i < terms.size(); i += size) {
      sums[0].add(terms[i]);
      sums[1].add(2 * terms[i]);
    }
    world->sum(sums);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(sums[0].value()), std::bit_cast<std::uint64_t>(serial.value()))
        << "seed " << seed << " rank " << rank << " of " << size;
    EXPECT_EQ(sums[1].value(), 2 * serial.value()) << "seed " << seed;
  }
}

// inf, -inf and NaN on some ranks: the same result whatever ranks hold them and in whatever order MPI adds.
TEST(MpiCommunicator, SpecialValuesPropagateInAnyOrder) {
  const int rank = world->rank();
  std::vector<mpm::ExactSum> sums(3);
  sums[0].add(rank == 0 ? INFINITY : 1.0);
  sums[1].add(rank == 0 ? INFINITY : -1.0);
  if (world->size() > 1) sums[1].add(rank == 1 ? -INFINITY : 0.0);
  sums[2].add(rank == world->size() - 1 ? NAN : 2.0);
  world->sum(sums);
  EXPECT_EQ(sums[0].value(), INFINITY);
  if (world->size() > 1) {
    EXPECT_TRUE(std::isnan(sums[1].value()));
  }
  EXPECT_TRUE(std::isnan(sums[2].value()));
}

TEST(MpiCommunicator, BoundsAndFlagsOverRanks) {
  const int rank = world->rank(), size = world->size();
  std::vector<double> high = {static_cast<double>(rank), -1.0 * rank, 3.5};
  std::vector<double> low = high;
  world->max(high);
  world->min(low);
  EXPECT_EQ(high[0], size - 1);
  EXPECT_EQ(high[1], 0.0);
  EXPECT_EQ(low[0], 0.0);
  EXPECT_EQ(low[1], -(size - 1.0));
  EXPECT_EQ(low[2], 3.5);
  EXPECT_TRUE(world->any(rank == size - 1));
  EXPECT_FALSE(world->any(false));
  world->barrier();
}

}  // namespace

int main(int argc, char** argv) {
  mpm::distributed::MpiCommunicator communicator(&argc, &argv);
  world = &communicator;
  ::testing::InitGoogleTest(&argc, argv);
  return mpm::test::run_on_every_rank(communicator);
}
