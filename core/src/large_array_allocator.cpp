// SPDX-License-Identifier: BSD-3-Clause
/// @file large_array_allocator.cpp
/// @brief Huge-page aligned, advised allocation of the large arrays.
#include "lsrecon/core/large_array_allocator.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace lsr::detail {

void* allocate_large_array(std::size_t bytes) {
  constexpr std::size_t kHugePage = std::size_t(2) << 20;
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: where it is refused (THP off, other kernels) the array keeps 4 KiB pages.
  madvise(p, rounded, MADV_HUGEPAGE);
#endif
  return p;
}

void free_large_array(void* p) noexcept { std::free(p); }

void populate_pages(const void* begin, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  // madvise wants a page-aligned start; the page holding live data keeps it (no write happens).
  constexpr std::uintptr_t kPage = 4096;
  const auto from = reinterpret_cast<std::uintptr_t>(begin) & ~(kPage - 1);
  const auto to = reinterpret_cast<std::uintptr_t>(begin) + bytes;
  madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);  // failure: faults stay where they were
#else
  (void)begin;
  (void)bytes;
#endif
}

}  // namespace lsr::detail
