// SPDX-License-Identifier: BSD-3-Clause
/// @file image_points.h
/// @brief 2D input from a binary image, as in the paper's first example: every dark pixel
/// (grey below half) is a data point at its centre, y up. PBM / PGM / PPM and PNG.
#pragma once

#include "lsrecon/core/types.h"

#include <string>

namespace lsr::adapters {

/// @throw lsr::Error for a missing or unreadable image or one with no dark pixel.
Points<2> read_image_points(const std::string& path);

}  // namespace lsr::adapters
