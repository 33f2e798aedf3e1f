// SPDX-License-Identifier: BSD-3-Clause
/// @file staged_outputs.h
/// @brief Every output of one command-line run, staged before the work starts and committed
/// together at its end: a run that fails or is interrupted anywhere leaves every existing file
/// as it was and no temporary behind.
#pragma once

#include "lsrecon/adapters/atomic_file.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lsr::demos {

class StagedOutputs {
 public:
  /// @param input the input file (empty for a generated cloud): no output may replace it.
  explicit StagedOutputs(std::string input) : input_(std::move(input)) {}

  /// @brief Checks `path` (its folder exists and is writable, it is no folder, not the input,
  /// not an output staged before) and creates its temporary.
  /// @return the temporary to write to.
  /// @throw lsr::Error saying which check failed.
  std::string stage(const std::string& path);

  /// @brief Moves every temporary onto its destination, in the order staged.
  void commit_all();

  /// @brief `message` with each temporary's name (and a writer's own temporary beside it) read
  /// as the destination's: what a user named, not a file that will not exist.
  static std::string in_destination_terms(std::string message);

 private:
  std::string input_;
  std::vector<StagedFile> files_;
  std::vector<std::filesystem::path> resolved_;  ///< each destination, absolute with links resolved
};

}  // namespace lsr::demos
