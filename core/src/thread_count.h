// SPDX-License-Identifier: BSD-3-Clause
/// @file thread_count.h
/// @brief The number of threads a stage asked for `threads` runs on (internal).
#pragma once

#include <omp.h>

namespace lsr::detail {

/// @brief `threads`, or all of OpenMP's for 0 (or less): every option's and stage's convention.
inline int thread_count(int threads) { return threads > 0 ? threads : omp_get_max_threads(); }

}  // namespace lsr::detail
