// SPDX-License-Identifier: BSD-3-Clause
/// @file worker_collectives.cpp
#include "sampling/worker_collectives.h"

#include <array>
#include <cstdint>

namespace lsr {
namespace {

// The order of doubles as the order of unsigned integers: negatives reversed below positives.
std::uint64_t ordered_bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof(b));
  return b >> 63 ? ~b : b | (std::uint64_t(1) << 63);
}

double from_ordered_bits(std::uint64_t b) {
  b = b >> 63 ? b & ~(std::uint64_t(1) << 63) : ~b;
  double v;
  std::memcpy(&v, &b, sizeof(v));
  return v;
}

}  // namespace

double median_over_workers(const TileExchange* x, const double* values, std::size_t n) {
  const std::size_t total = sum_over_workers(x, n);
  if (total == 0) return 0.0;
  std::size_t rank = total / 2;  // among the values that share the prefix found so far
  std::uint64_t prefix = 0;
  for (int shift = 56; shift >= 0; shift -= 8) {
    const std::uint64_t high = shift == 56 ? 0 : ~std::uint64_t(0) << (shift + 8);
    std::array<std::size_t, 256> count{};
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t b = ordered_bits(values[i] + 0.0);  // -0.0 and 0.0 compare equal: one key
      if ((b & high) == prefix) ++count[(b >> shift) & 0xff];
    }
    const std::vector<std::array<std::size_t, 256>> each = all_gather(x, count);
    std::size_t digit = 0;
    for (;; ++digit) {
      std::size_t c = 0;
      for (const auto& w : each) c += w[digit];
      if (rank < c) break;
      rank -= c;
    }
    prefix |= std::uint64_t(digit) << shift;
  }
  return from_ordered_bits(prefix);
}

}  // namespace lsr
