// SPDX-License-Identifier: BSD-3-Clause
/// @file point_validation.cpp
#include "sampling/point_validation.h"

#include "lsrecon/core/errors.h"

namespace lsr {

template <int D>
Points<D> drop_non_finite(const Points<D>& points) {
  Points<D> kept;
  kept.reserve(points.size());
  for (const auto& p : points) {
    if (p.allFinite()) kept.push_back(p);
  }
  return kept;
}

template <int D>
void require_valid_points(const Points<D>& points, const std::string& what) {
  if (points.empty()) {
    throw InvalidInput(what + ": the point set is empty", "pass at least one point");
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      throw InvalidInput(what + ": point " + std::to_string(i) + " has a NaN or infinite coordinate",
                         "remove non-finite points first (lsr::drop_non_finite)");
    }
  }
}

template Points<2> drop_non_finite<2>(const Points<2>&);
template Points<3> drop_non_finite<3>(const Points<3>&);
template void require_valid_points<2>(const Points<2>&, const std::string&);
template void require_valid_points<3>(const Points<3>&, const std::string&);

}  // namespace lsr
