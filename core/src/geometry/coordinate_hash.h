// SPDX-License-Identifier: BSD-3-Clause
/// @file coordinate_hash.h
/// @brief A hash of N coordinates by their bits, for keys that are equal only when every bit is
/// (mesh vertices shared by tiles, edges by their ends): FNV-1a over the 64-bit words.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace lsr {

template <std::size_t N>
struct CoordinateHash {
  std::size_t operator()(const std::array<double, N>& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (double x : k) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &x, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return std::size_t(h ^ (h >> 32));
  }
};

}  // namespace lsr
