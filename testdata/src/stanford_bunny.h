// SPDX-License-Identifier: BSD-3-Clause
/// @file stanford_bunny.h (compiled from data/stanford_bunny.off)
/// @brief The Stanford bunny's closed triangle mesh, for the test corpus (shape_corpus.cpp).
#pragma once

#include <array>

namespace lsr {

extern const std::array<double, 3> kBunnyVertices[1839];
extern const std::array<int, 3> kBunnyTriangles[3674];

}  // namespace lsr
