#include "mpm/reserved_pages.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
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

void release_pages(void* first, std::size_t bytes) noexcept {
  const std::size_t page = page_bytes();
  const auto a = reinterpret_cast<std::uintptr_t>(first);
  const std::uintptr_t lo = round_up(a, page), hi = round_down(a + bytes, page);
  // MADV_DONTNEED on private anonymous memory: the pages are dropped and read as zeros when touched again.
  if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_DONTNEED);
}

std::size_t resident_bytes(const void* first, std::size_t bytes) {
  if (bytes == 0) return 0;
  const std::size_t page = page_bytes();
  const auto a = reinterpret_cast<std::uintptr_t>(first);
  const std::uintptr_t lo = round_down(a, page), hi = round_up(a + bytes, page);
  std::vector<unsigned char> in((hi - lo) / page);
  if (mincore(reinterpret_cast<void*>(lo), hi - lo, in.data()) != 0) return 0;
  std::size_t n = 0;
  for (unsigned char c : in) n += c & 1;
  return n * page;
}

}  // namespace mpm
