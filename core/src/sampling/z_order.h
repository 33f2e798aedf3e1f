// SPDX-License-Identifier: BSD-3-Clause
/// @file z_order.h
/// @brief Z-order (Morton) numbering of points in the unit box: points near each other in space
/// get numbers near each other, so that loops over them touch memory (and kd-tree cells) in
/// order.
#pragma once

#include "lsrecon/core/types.h"

#include <cstdint>
#include <vector>

namespace lsr {

/// @brief The Morton key of x: its coordinates, clamped to [0, 1] and quantised to 64 / D bits
/// each, with their bits interleaved.
template <int D>
std::uint64_t morton_key(const Vec<D>& x);

/// @brief The indices of the points in Z-order (ties, which need points closer than 2^(-64/D),
/// by index).
template <int D>
std::vector<Index> z_order(const Points<D>& points);

}  // namespace lsr
