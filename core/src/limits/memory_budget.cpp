// SPDX-License-Identifier: BSD-3-Clause
/// @file memory_budget.cpp
#include "limits/memory_budget.h"

#include "lsrecon/core/errors.h"

#include <unistd.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace lsr::detail {

double memory_budget(const ReconstructionOptions& o) {
  if (o.limits.max_memory > 0.0) return o.limits.max_memory;
  const double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  return 0.5 * physical;
}

std::string gib(double bytes) {
  std::ostringstream s;
  s << std::setprecision(3) << bytes / double(1 << 30) << " GiB";
  return s.str();
}

template <int D>
Index memory_limited_vertices(const ReconstructionOptions& o, std::size_t points) {
  const double budget = memory_budget(o);
  const double for_points = double(points) * kBytesPerPoint;
  const double vertices = (budget - for_points) / kBytesPerVertex<D>;
  if (vertices < 1e4) {
    throw ResourceLimit(std::to_string(points) + " points need about " + gib(for_points + 1e4 * kBytesPerVertex<D>) +
                            ", more than the memory limit of " + gib(budget),
                        "raise max_memory (lsrecon --max-memory GiB) or subsample the cloud");
  }
  return Index(std::min(vertices, 2e9));
}

template Index memory_limited_vertices<2>(const ReconstructionOptions& o, std::size_t points);
template Index memory_limited_vertices<3>(const ReconstructionOptions& o, std::size_t points);

}  // namespace lsr::detail
