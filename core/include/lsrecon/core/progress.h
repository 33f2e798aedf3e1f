// SPDX-License-Identifier: BSD-3-Clause
/// @file progress.h
/// @brief Progress reporting and cancellation for long operations.
#pragma once

#include "lsrecon/core/errors.h"

#include <functional>
#include <string>
#include <utility>

namespace lsr {

/// @brief Called with a stage name and a fraction in [0, 1] (or -1 when unknown); returns
/// false to ask the operation to stop.
using ProgressCallback = std::function<bool(const std::string& stage, double fraction)>;

/// @brief Wraps an optional ProgressCallback; long loops call update() once per outer
/// iteration, which throws lsr::Cancelled when the callback asks to stop.
class Progress {
 public:
  Progress() = default;
  explicit Progress(ProgressCallback callback) : callback_(std::move(callback)) {}

  /// @throw Cancelled if the callback returned false.
  void update(const std::string& stage, double fraction) const {
    if (callback_ && !callback_(stage, fraction)) throw Cancelled(stage);
  }

 private:
  ProgressCallback callback_;
};

}  // namespace lsr
