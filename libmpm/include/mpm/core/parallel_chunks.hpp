#pragma once
/// \file parallel_chunks.hpp
/// A parallel loop over chunks of an index range whose task machinery is compiled once, in the engine, not once per
/// loop. `tbb::parallel_for` instantiates its task type, its partitioner's work balancing and their type information
/// for every lambda it is given; the schemes' kernels are instantiated per (scheme, shape function, dimension), so
/// those copies were most of the code the make_scheme units generated. Here the loop body is reached through one
/// indirect call per chunk (thousands of particles or nodes), and the body's own loop is compiled and inlined as
/// before. The chunks are TBB's: the same auto partitioner and grain as `tbb::parallel_for(blocked_range(...))`.

#include <cstddef>
#include <memory>
#include <type_traits>

#include "mpm/core/types.hpp"

namespace mpm {

namespace detail {
using ChunkCall = void (*)(void* body, Index begin, Index end);
/// tbb::parallel_for over [begin, end) with `grain`, calling call(body, chunk_begin, chunk_end) per chunk.
void parallel_chunks_erased(Index begin, Index end, std::size_t grain, ChunkCall call, void* body);
}  // namespace detail

/// Calls body(chunk_begin, chunk_end) for disjoint chunks covering [begin, end), in parallel; each chunk holds at
/// most about `grain` indices when the range is split (TBB's blocked_range semantics). The order of the calls is free.
template <class Int, class Body>
void parallel_chunks(Int begin, Int end, std::size_t grain, Body&& body) {
  using B = std::remove_reference_t<Body>;
  detail::parallel_chunks_erased(
      static_cast<Index>(begin), static_cast<Index>(end), grain,
      [](void* b, Index lo, Index hi) { (*static_cast<B*>(b))(static_cast<Int>(lo), static_cast<Int>(hi)); },
      const_cast<void*>(static_cast<const void*>(std::addressof(body))));
}

}  // namespace mpm
