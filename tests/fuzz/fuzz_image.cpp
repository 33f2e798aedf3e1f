// SPDX-License-Identifier: BSD-3-Clause
/// @file fuzz_image.cpp
/// @brief libFuzzer harness for the image reader (2D input): the first byte picks PGM/PPM/PBM or
/// PNG, the rest is the file. lsr::Error is a clean refusal; anything else is a finding.
#include "image_points.h"
#include "lsrecon/core/errors.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const kFormats[] = {"pgm", "ppm", "pbm", "png"};
  if (size == 0) return 0;
  const std::string path = "/tmp/lsrecon-fuzz-" + std::to_string(::getpid()) + "." + kFormats[data[0] % 4];
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  }
  try {
    (void)lsr::demos::read_image_points(path);
  } catch (const lsr::Error&) {
  }
  std::remove(path.c_str());
  return 0;
}
