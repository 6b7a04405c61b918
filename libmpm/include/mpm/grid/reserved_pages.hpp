#pragma once
/// \file reserved_pages.hpp
/// Node arrays whose memory follows the particles (docs/distributed.md §5.10). A grid's
/// node arrays are sized by its bounding box, but a step's kernels touch only the nodes its particles reach
/// (ActiveTiles). An array allocated here is reserved address space: the operating system gives a page physical
/// memory when a kernel first writes it (zero-filled), so a region of the grid no particle ever reaches costs no
/// memory, and `release_pages` hands the pages of a region the particles left back to the system.
///
/// The elements are default-initialised: a fresh array of trivially constructible records reads as zeros (the
/// pages are zero-filled) without a write, where a value-initialising std::vector would write every page.

#include <cstddef>
#include <new>
#include <type_traits>
#include <utility>

namespace mpm {

/// Bytes of a memory page.
std::size_t page_bytes();

/// Raw storage: zero-filled; `bytes` of at least a few pages are reserved address space (pages backed when first
/// written), smaller requests come from the heap. Throws std::bad_alloc.
void* reserve_zeroed(std::size_t bytes);
/// Frees what reserve_zeroed(bytes) returned.
void free_reserved(void* p, std::size_t bytes) noexcept;

/// Gives the whole pages inside [first, first + bytes) back to the system; they read as zeros afterwards. For
/// storage from reserve_zeroed whose content there is zero or no longer needed.
void release_pages(void* first, std::size_t bytes) noexcept;

/// Zeroes [first, first + bytes): the whole pages inside are given back (release_pages), the parts of pages at the
/// two ends written.
void zero_bytes(void* first, std::size_t bytes) noexcept;

/// Bytes of [first, first + bytes) whose pages are in memory (counted per whole page that the range touches).
std::size_t resident_bytes(const void* first, std::size_t bytes);

/// std::allocator replacement for node arrays: reserve_zeroed storage, default-initialising construct().
template <class T>
struct ReservedPages {
  static_assert(alignof(T) <= alignof(std::max_align_t), "ReservedPages: over-aligned element type");
  using value_type = T;

  ReservedPages() = default;
  template <class U>
  ReservedPages(const ReservedPages<U>&) noexcept {}  // NOLINT(google-explicit-constructor): allocator rebinding

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(reserve_zeroed(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { free_reserved(p, n * sizeof(T)); }

  /// Default-initialisation: no write for trivially constructible records (the zero-filled pages stay untouched).
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  friend bool operator==(const ReservedPages&, const ReservedPages&) noexcept { return true; }
};

}  // namespace mpm
