#include "mpm/core/parallel_chunks.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace mpm::detail {

void parallel_chunks_erased(Index begin, Index end, std::size_t grain, ChunkCall call, void* body) {
  if (end <= begin) return;
  tbb::parallel_for(tbb::blocked_range<Index>(begin, end, grain),
                    [&](const tbb::blocked_range<Index>& r) { call(body, r.begin(), r.end()); });
}

}  // namespace mpm::detail
