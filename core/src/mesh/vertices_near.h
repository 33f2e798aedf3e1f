// SPDX-License-Identifier: BSD-3-Clause
/// @file vertices_near.h
/// @brief Mesh vertices within a distance of flagged vertices.
#pragma once

#include "lsrecon/core/types.h"

#include <vector>

namespace lsr::detail {

// Flags the vertices within `radius` of a `seed` vertex (all false without seeds).
template <int D>
std::vector<char> near_any(const Points<D>& vertices, const std::vector<char>& seed, double radius, int threads);

}  // namespace lsr::detail
