// SPDX-License-Identifier: BSD-3-Clause
/// @file errors.h
/// @brief The exceptions the core throws: bad input, resource limits, cancellation.
#pragma once

#include <stdexcept>
#include <string>

namespace lsr {

/// @brief Base of every error lsrecon reports. what() says what went wrong and, after
/// "[hint: ...]", what to change.
class Error : public std::runtime_error {
 public:
  Error(const std::string& what, const std::string& hint)
      : std::runtime_error(hint.empty() ? what : what + " [hint: " + hint + "]") {}
};

/// @brief Input the algorithm cannot work with (empty, non-finite, degenerate, bad parameter).
class InvalidInput : public Error {
 public:
  using Error::Error;
};

/// @brief The work would exceed a stated limit (memory, mesh size) and was refused before
/// allocating it.
class ResourceLimit : public Error {
 public:
  using Error::Error;
};

/// @brief The caller's progress callback asked to stop.
class Cancelled : public Error {
 public:
  explicit Cancelled(const std::string& stage) : Error("cancelled during " + stage, "") {}
};

}  // namespace lsr
