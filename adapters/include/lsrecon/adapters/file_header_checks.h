// SPDX-License-Identifier: BSD-3-Clause
/// @file file_header_checks.h
/// @brief Checks what a file's header declares against what the file can hold, before a
/// third-party reader (PCL, OpenMesh, VTK) reserves memory for it: a 10-line PCD declaring a
/// billion points made PCL allocate 11 GiB, a PGM declaring 99999 x 99999 pixels 16 GiB.
#pragma once

#include <string>

namespace lsr::adapters {

/// @brief Throws lsr::Error if `path` is a directory, a FIFO, a socket or a device (a missing
/// path passes: opening it says so).
void require_regular_file(const std::string& path);

/// @brief Throws lsr::Error (with a hint) when the header of `path` is malformed or declares
/// more elements than its size allows. Formats by extension: ply, off, stl, pgm / ppm /
/// pnm, png; any other extension (no counts in the header: xyz, obj) passes.
void check_declared_size(const std::string& path);

}  // namespace lsr::adapters
