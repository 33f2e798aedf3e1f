// SPDX-License-Identifier: BSD-3-Clause
/// @file fuzz_point_file.cpp
/// @brief libFuzzer harness for every point reader lsrecon owns or wraps: the first byte picks
/// the format (xyz, ply, pcd, off, obj, stl), the rest is the file. Any lsr::Error is a clean
/// refusal; a crash, a sanitizer report, a hang or an out-of-memory is a finding.
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/core/errors.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const kFormats[] = {"xyz", "ply", "pcd", "off", "obj", "stl"};
  if (size == 0) return 0;
  const std::string path = "/tmp/lsrecon-fuzz-" + std::to_string(::getpid()) + "." + kFormats[data[0] % 6];
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  }
  try {
    (void)lsr::adapters::read_point_file(path);
  } catch (const lsr::Error&) {
  }
  std::remove(path.c_str());
  return 0;
}
