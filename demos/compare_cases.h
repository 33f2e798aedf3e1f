// SPDX-License-Identifier: BSD-3-Clause
/// @file compare_cases.h
/// @brief The generated test clouds of lsrecon-compare, with their ground truth: signed
/// distance, true normals and a dense sample of the true surface.
#pragma once

#include "lsrecon/core/types.h"

#include <functional>
#include <string>
#include <vector>

namespace lsr::demos {

struct CompareCase {
  std::string name;
  Points<3> points;        ///< what the methods see (noisy when asked)
  Points<3> normals;       ///< true outward normals at the clean positions
  std::function<double(const Vec<3>&)> sdf;  ///< the true surface's signed distance
  Points<3> truth;         ///< a dense sample of the true surface
  double diagonal = 1.0;   ///< bounding-box diagonal of the truth
};

/// @brief sphere, torus, two-spheres or dumbbell (two balls joined by a thin bar: a thin part
/// and concave joins). noise: Gaussian deviation relative to the diagonal; holes: fraction of
/// the points removed in a few caps; nonuniform: density varies 10x across the shape.
/// @throw lsr::InvalidInput for an unknown name.
CompareCase make_case(const std::string& name, int points, double noise, double holes, bool nonuniform);

/// @brief The names make_case() knows.
std::vector<std::string> case_names();

}  // namespace lsr::demos
