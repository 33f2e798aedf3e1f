// SPDX-License-Identifier: BSD-3-Clause
/// @file header_lines.h
/// @brief The text header of a PLY or PCD file, split into words, and where its body begins
/// (internal to the readers and the header checks).
#pragma once

#include "lsrecon/core/errors.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace lsr::adapters::detail {

/// @brief Opens `path` for binary reading into `in`; returns its size in bytes.
/// @throw lsr::Error if it cannot be opened or sized.
inline double open_sized(const std::string& path, std::ifstream& in) {
  in.open(path, std::ios::binary);
  if (!in) throw Error("cannot open " + path, "check the path and the file's permissions");
  std::error_code error;
  const double size = double(std::filesystem::file_size(path, error));
  if (error) throw Error("cannot read the size of " + path, "pass a regular file");
  return size;
}

/// @brief A header larger than this is refused: real ones are a few hundred bytes.
constexpr std::streamoff kMaxHeaderBytes = 65536;

/// @brief Header lines up to and including the first whose first word is `last`, each split in
/// words (blank lines, and '#' comments if `hash_comments`, left out); `body` is then the
/// offset of the byte after that line. False if the stream ends, or kMaxHeaderBytes pass, first.
inline bool read_header_lines(std::istream& in, const std::string& last, bool hash_comments,
                              std::vector<std::vector<std::string>>& lines, std::streamoff& body) {
  std::string line;
  while (std::getline(in, line)) {
    if (in.tellg() > kMaxHeaderBytes) return false;
    std::istringstream s(line);
    std::vector<std::string> words;
    for (std::string w; s >> w;) words.push_back(w);
    if (!words.empty() && !(hash_comments && words[0][0] == '#')) lines.push_back(words);
    if (!words.empty() && words[0] == last) {
      body = in.tellg();
      return body >= 0;
    }
  }
  return false;
}

/// @brief A count from a header: a non-negative decimal integer below 2^53, nothing else.
inline double parse_header_count(const std::string& path, const std::string& token) {
  const bool digits = !token.empty() && token.size() <= 15 && token.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) {
    throw Error(path + ": '" + printable(token) + "' in the header is not a count",
                "the file is corrupt or truncated; re-export it");
  }
  return std::stod(token);
}

/// @brief Throws unless the `minimum_bytes` that `declared` elements (counted as `what`) take at
/// least fit in the `available` bytes after the header: before anything is allocated for them.
inline void require_declared_fits(const std::string& path, double declared, double minimum_bytes, double available,
                                  const std::string& what) {
  if (minimum_bytes > available) {
    std::ostringstream s;
    s << path << ": the header declares " << declared << ' ' << what << ", which need at least " << minimum_bytes
      << " bytes, but the file has " << std::max(available, 0.0);
    throw Error(s.str(), "the file is corrupt or truncated; re-export it");
  }
}

}  // namespace lsr::adapters::detail
