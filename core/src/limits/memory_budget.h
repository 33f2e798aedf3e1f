// SPDX-License-Identifier: BSD-3-Clause
/// @file memory_budget.h
/// @brief How many mesh vertices fit in the memory budget beside the points.
#pragma once

#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/types.h"

#include <string>

namespace lsr::detail {

// Peak memory per input point and per mesh vertex, measured on random samples and rounded up:
// trefoil 200k and 1M points at the same 327k vertices peaked at 495 and 929 MiB (0.56 KB per
// point), and with that the 200k sphere, torus and trefoil at 0.99, 0.97 and 1.2 KB per 3D
// vertex. 2D: 2 KB per vertex, measured before G^T stopped being stored.
constexpr double kBytesPerPoint = 1000.0;
template <int D>
constexpr double kBytesPerVertex = D == 3 ? 1300.0 : 2000.0;

// max_memory, or half the physical memory (a 10M-point cloud needs about 8 GiB).
double memory_budget(const ReconstructionOptions& o);

std::string gib(double bytes);

// The mesh vertices that fit in the budget beside the points; refuses a cloud that alone
// would not.
template <int D>
Index memory_limited_vertices(const ReconstructionOptions& o, std::size_t points);

}  // namespace lsr::detail
