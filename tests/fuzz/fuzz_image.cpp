// SPDX-License-Identifier: BSD-3-Clause
/// @file fuzz_image.cpp
/// @brief libFuzzer harness for the image reader (2D input): pgm, ppm, pbm, png (see fuzz_file.h).
#include "fuzz_file.h"
#include "lsrecon/adapters/image_points.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const kFormats[] = {"pgm", "ppm", "pbm", "png"};
  return fuzz_file(data, size, kFormats, [](const std::string& path) { (void)lsr::adapters::read_image_points(path); });
}
