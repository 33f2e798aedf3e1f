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

}  // namespace lsr
