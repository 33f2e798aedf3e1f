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
void require_cloud_fits(const ReconstructionOptions& o, std::size_t points) {
  const double budget = memory_budget(o), needed = double(points) * kBytesPerPoint + 1e4 * kBytesPerVertex<D>;
  if (needed > budget) {
    throw ResourceLimit(std::to_string(points) + " points need about " + gib(needed) + ", more than the memory limit of " + gib(budget),
                        "raise max_memory (lsrecon --max-memory GiB), subsample the cloud, or share it among MPI ranks (lsrecon-mpi)");
  }
}

template <int D>
Index memory_limited_vertices(const ReconstructionOptions& o, std::size_t points, std::size_t sample) {
  const double left_out = points > sample ? double(points - sample) : 0.0;
  const double held = double(sample) * kBytesPerPoint + left_out * kBytesPerLeftOutPoint;
  return Index(std::clamp((memory_budget(o) - held) / kBytesPerVertex<D>, 1e4, 2e9));
}

template void require_cloud_fits<2>(const ReconstructionOptions& o, std::size_t points);
template void require_cloud_fits<3>(const ReconstructionOptions& o, std::size_t points);
template Index memory_limited_vertices<2>(const ReconstructionOptions& o, std::size_t points, std::size_t sample);
template Index memory_limited_vertices<3>(const ReconstructionOptions& o, std::size_t points, std::size_t sample);

}  // namespace lsr::detail
