// SPDX-License-Identifier: BSD-3-Clause
/// @file large_array_allocator.h
/// @brief An allocator for the solver's largest arrays (the bisection forest, the mesh
/// candidates, the edge graph, the balls, G): backed by transparent huge pages where the
/// system offers them.
///
/// Arrays of tens to hundreds of MiB are mapped fresh by malloc and first touched page by page:
/// on the 200k-point torus those 4 KiB page faults took 8% of the run on a virtual machine
/// (measured, perf). Aligned to 2 MiB and advised MADV_HUGEPAGE, such an array faults once per
/// 2 MiB. Small arrays keep the ordinary allocator.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <new>
#include <vector>

namespace lsr {

namespace detail {
/// Arrays from this size on are allocated on huge-page boundaries and advised.
inline constexpr std::size_t kLargeArrayBytes = std::size_t(4) << 20;
/// @throw std::bad_alloc
void* allocate_large_array(std::size_t bytes);
void free_large_array(void* p) noexcept;
/// Faults in the pages of [begin, begin + bytes) writable, their contents unchanged; where
/// the system cannot (kernels before 5.14), nothing.
void populate_pages(const void* begin, std::size_t bytes) noexcept;
}  // namespace detail

template <class T>
struct LargeArrayAllocator {
  static_assert(alignof(T) <= alignof(std::max_align_t), "over-aligned types need their own allocator");
  using value_type = T;

  LargeArrayAllocator() = default;
  template <class U>
  LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < detail::kLargeArrayBytes) return static_cast<T*>(::operator new(bytes));
    return static_cast<T*>(detail::allocate_large_array(bytes));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < detail::kLargeArrayBytes) {
      ::operator delete(p);
    } else {
      detail::free_large_array(p);
    }
  }
  template <class U>
  bool operator==(const LargeArrayAllocator<U>&) const noexcept { return true; }
  template <class U>
  bool operator!=(const LargeArrayAllocator<U>&) const noexcept { return false; }
};

/// A std::vector whose storage, once large, lies on huge pages.
template <class T>
using LargeVector = std::vector<T, LargeArrayAllocator<T>>;

/// @brief The storage of elements [from, to) of v, clamped to its capacity: what a later
/// push_back or resize will first touch. Read before another thread grows v, and passed to
/// populate() there, it lets that thread take the page faults (zeroing fresh huge pages took
/// 0.1 to 2.8 s per GiB on the virtual machines measured) while this one works.
struct StorageRange {
  const void* begin = nullptr;
  std::size_t bytes = 0;
};
template <class T>
StorageRange storage_range(const LargeVector<T>& v, std::size_t from, std::size_t to) {
  to = std::min(to, v.capacity());
  return from < to ? StorageRange{v.data() + from, (to - from) * sizeof(T)} : StorageRange{};
}
/// @brief Faults the range in (detail::populate_pages): contents unchanged, so it may run while
/// another thread writes there, or after the storage moved (then it touches unused memory).
inline void populate(const StorageRange& r) noexcept {
  if (r.bytes > 0) detail::populate_pages(r.begin, r.bytes);
}

}  // namespace lsr
