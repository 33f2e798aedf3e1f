// SPDX-License-Identifier: BSD-3-Clause
/// @file stage_clock.h
/// @brief Wall time per pipeline stage, in the order the stages first ran (internal).
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace lsr::detail {

class StageClock {
 public:
  StageClock(std::map<std::string, double>& seconds, std::vector<std::string>& order) : seconds_(seconds), order_(order) {}
  /// @brief Adds the time since the last end() (or construction) to `stage`.
  void end(const std::string& stage) {
    const auto now = std::chrono::steady_clock::now();
    if (!seconds_.count(stage)) order_.push_back(stage);
    seconds_[stage] += std::chrono::duration<double>(now - start_).count();
    start_ = now;
  }

 private:
  std::map<std::string, double>& seconds_;
  std::vector<std::string>& order_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace lsr::detail
