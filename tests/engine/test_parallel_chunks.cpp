// mpm::parallel_chunks (mpm/core/parallel_chunks.hpp), the engine's one parallel loop: its chunks cover the range
// exactly once, none is empty or larger than the grain, and the body sees the index type it was given.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <atomic>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "mpm/core/parallel_chunks.hpp"

namespace {

TEST(ParallelChunks, CoverTheRangeOnceInChunksNoLargerThanTheGrain) {
  const tbb::global_control two_threads(tbb::global_control::max_allowed_parallelism, 2);
  const mpm::Index begin = 17, end = 100'003;
  const std::size_t grain = 1000;
  std::vector<std::atomic<int>> visits(static_cast<std::size_t>(end));
  std::atomic<int> chunks{0}, empty{0}, oversized{0};
  mpm::parallel_chunks(begin, end, grain, [&](mpm::Index chunk_begin, mpm::Index chunk_end) {
    ++chunks;
    if (chunk_end <= chunk_begin) ++empty;
    if (chunk_end - chunk_begin > static_cast<mpm::Index>(grain)) ++oversized;
    for (mpm::Index i = chunk_begin; i < chunk_end; ++i) ++visits[static_cast<std::size_t>(i)];
  });
  for (mpm::Index i = 0; i < end; ++i)
    ASSERT_EQ(visits[static_cast<std::size_t>(i)], i < begin ? 0 : 1) << "index " << i;
  EXPECT_EQ(empty, 0);
  EXPECT_EQ(oversized, 0);
  EXPECT_GE(chunks, static_cast<int>((end - begin) / static_cast<mpm::Index>(grain)));
}

TEST(ParallelChunks, AnEmptyRangeCallsNothingAndUnsignedIndicesStayUnsigned) {
  int calls = 0;
  mpm::parallel_chunks(mpm::Index{5}, mpm::Index{5}, 1, [&](mpm::Index, mpm::Index) { ++calls; });
  mpm::parallel_chunks(mpm::Index{9}, mpm::Index{3}, 1, [&](mpm::Index, mpm::Index) { ++calls; });
  EXPECT_EQ(calls, 0);
  std::atomic<std::size_t> sum{0};
  mpm::parallel_chunks(std::size_t{0}, std::size_t{10}, 1, [&](auto lo, auto hi) {
    static_assert(std::is_same_v<decltype(lo), std::size_t>);
    for (auto i = lo; i < hi; ++i) sum += i;
  });
  EXPECT_EQ(sum, 45u);
}

}  // namespace
