// SPDX-License-Identifier: BSD-3-Clause
/// @file fuzz_point_file.cpp
/// @brief libFuzzer harness for every point reader lsrecon owns or wraps: xyz, ply, pcd, off,
/// obj, stl (see fuzz_file.h).
#include "fuzz_file.h"
#include "lsrecon/adapters/point_files.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const kFormats[] = {"xyz", "ply", "pcd", "off", "obj", "stl"};
  return fuzz_file(data, size, kFormats, [](const std::string& path) { (void)lsr::adapters::read_point_file(path); });
}
