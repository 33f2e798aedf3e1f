// SPDX-License-Identifier: BSD-3-Clause
/// @file stopwatch.h
/// @brief Wall-clock timing of pipeline stages and peak memory, for the demos and benchmarks.
#pragma once

#include <sys/resource.h>

#include <chrono>

namespace lsr::demos {

class Stopwatch {
 public:
  /// Seconds since construction or the last lap(), and restarts.
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// @brief Peak resident memory of this process so far, MiB.
inline double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

}  // namespace lsr::demos
