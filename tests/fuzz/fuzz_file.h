// SPDX-License-Identifier: BSD-3-Clause
/// @file fuzz_file.h
/// @brief What every reader harness does: the first byte picks the format, the rest becomes a
/// temporary file of that extension, read(path) runs on it; lsr::Error is a clean refusal,
/// anything else (crash, sanitizer report, uncaught exception, hang, OOM) is a finding.
#pragma once

#include "lsrecon/core/errors.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

template <std::size_t N, class Read>
int fuzz_file(const std::uint8_t* data, std::size_t size, const char* const (&formats)[N], Read read) {
  if (size == 0) return 0;
  const std::string path = "/tmp/lsrecon-fuzz-" + std::to_string(::getpid()) + "." + formats[data[0] % N];
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  }
  try {
    read(path);
  } catch (const lsr::Error&) {
  }
  std::remove(path.c_str());
  return 0;
}
