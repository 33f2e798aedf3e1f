// SPDX-License-Identifier: BSD-3-Clause
/// @file atomic_file.cpp
#include "lsrecon/core/atomic_file.h"

#include "lsrecon/core/errors.h"

#include <cstdio>

namespace lsr {

void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string&)>& write) {
  // Keep the extension: writers pick the format from it (out.ply -> out.partial.ply).
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string temporary =
      has_extension ? path.substr(0, dot) + ".partial" + path.substr(dot) : path + ".partial";
  try {
    write(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw Error("cannot move the finished file onto " + path,
                "check that the output folder exists and is writable");
  }
}

}  // namespace lsr
