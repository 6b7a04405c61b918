#include "mpm/grid/reserved_pages.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace mpm {
namespace {

/// Below this, a request comes from the heap (calloc): a mapping per small array would waste a page and a system
/// call, and the node arrays that matter are far larger.
constexpr std::size_t mapped_from = std::size_t{1} << 16;

std::uintptr_t round_down(std::uintptr_t a, std::size_t page) { return a / page * page; }
std::uintptr_t round_up(std::uintptr_t a, std::size_t page) { return (a + page - 1) / page * page; }

}  // namespace

std::size_t page_bytes() {
  static const std::size_t bytes = [] {
    const long p = sysconf(_SC_PAGESIZE);
    return p > 0 ? static_cast<std::size_t>(p) : std::size_t{4096};
  }();
  return bytes;
}

void* reserve_zeroed(std::size_t bytes) {
  if (bytes == 0) bytes = 1;
  if (bytes < mapped_from) {
    if (void* p = std::calloc(bytes, 1)) return p;
    throw std::bad_alloc();
  }
  // MAP_NORESERVE: no swap is set aside for pages never written (a large, mostly empty grid).
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  // Small pages even where transparent huge pages are always on: one touched node would otherwise bring 2 MiB in.
  madvise(p, bytes, MADV_NOHUGEPAGE);
  return p;
}

void free_reserved(void* p, std::size_t bytes) noexcept {
  if (!p) return;
  if (bytes == 0) bytes = 1;
  if (bytes < mapped_from)
    std::free(p);
  else
    munmap(p, bytes);
}

/// The pages of [first, first + bytes) as offsets from `first`: `inner_*` the whole pages inside, `outer_*` every
/// page the range touches (offsets, so that no integer becomes a pointer again).
struct PageSpan {
  std::ptrdiff_t inner_first, inner_end, outer_first, outer_end;
};
PageSpan page_span(const void* first, std::size_t bytes) {
  const std::size_t page = page_bytes();
  const auto a = reinterpret_cast<std::uintptr_t>(first);
  const auto offset = [a](std::uintptr_t at) {
    return static_cast<std::ptrdiff_t>(at) - static_cast<std::ptrdiff_t>(a);
  };
  return {offset(round_up(a, page)), offset(round_down(a + bytes, page)), offset(round_down(a, page)),
          offset(round_up(a + bytes, page))};
}

void release_pages(void* first, std::size_t bytes) noexcept {
  const PageSpan s = page_span(first, bytes);
  // MADV_DONTNEED on private anonymous memory: the pages are dropped and read as zeros when touched again.
  if (s.inner_end > s.inner_first)
    madvise(static_cast<std::byte*>(first) + s.inner_first, static_cast<std::size_t>(s.inner_end - s.inner_first),
            MADV_DONTNEED);
}

void zero_bytes(void* first, std::size_t bytes) noexcept {
  auto* base = static_cast<std::byte*>(first);
  const PageSpan s = page_span(first, bytes);
  const auto size = static_cast<std::ptrdiff_t>(bytes);
  // A part of a page at either end is written only if its page is in memory: one that is not reads as zeros
  // already, and writing it would bring it in.
  const auto clear = [&](std::ptrdiff_t from, std::ptrdiff_t to) {
    const auto n = static_cast<std::size_t>(to - from);
    if (to > from && resident_bytes(base + from, n) > 0) std::memset(base + from, 0, n);
  };
  if (s.inner_end <= s.inner_first) {
    clear(0, size);
    return;
  }
  clear(0, s.inner_first);
  clear(s.inner_end, size);
  release_pages(base + s.inner_first, static_cast<std::size_t>(s.inner_end - s.inner_first));
}

std::size_t resident_bytes(const void* first, std::size_t bytes) {
  if (bytes == 0) return 0;
  const std::size_t page = page_bytes();
  const PageSpan s = page_span(first, bytes);
  const auto span = static_cast<std::size_t>(s.outer_end - s.outer_first);
  std::vector<unsigned char> in(span / page);
  // mincore wants a page-aligned start: the page that holds `first`.
  void* start = const_cast<std::byte*>(static_cast<const std::byte*>(first) + s.outer_first);
  if (mincore(start, span, in.data()) != 0) return span;  // unknown: say all
  std::size_t n = 0;
  for (unsigned char c : in) n += c & 1;
  return n * page;
}

}  // namespace mpm
