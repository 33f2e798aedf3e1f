// SPDX-License-Identifier: BSD-3-Clause
/// @file point_validation.h
/// @brief Checks on input point sets, with messages that say what to change.
#pragma once

#include "lsrecon/core/types.h"

#include <string>

namespace lsr {

/// @brief Copy of points without those that have a NaN or infinite coordinate.
template <int D>
Points<D> drop_non_finite(const Points<D>& points);

/// @throw InvalidInput if points is empty or holds a non-finite coordinate; what names them.
template <int D>
void require_valid_points(const Points<D>& points, const std::string& what);

}  // namespace lsr
