// SPDX-License-Identifier: BSD-3-Clause
/// @file errors.h
/// @brief The exceptions the core throws: bad input, resource limits, cancellation.
#pragma once

#include <cstdio>
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

/// @brief Text taken from an input file, made safe to put in a message: printable ASCII kept,
/// any other byte written as \xHH (a NUL would cut the message, an escape sequence would reach
/// the terminal), and cut to `max_bytes` with "..." after.
inline std::string printable(const std::string& text, std::size_t max_bytes = 60) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < max_bytes; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += char(c);
    } else {
      char hex[5];
      std::snprintf(hex, sizeof(hex), "\\x%02x", c);
      out += hex;
    }
  }
  if (text.size() > max_bytes) out += "...";
  return out;
}

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
