// SPDX-License-Identifier: BSD-3-Clause
/// @file compare_cases.h
/// @brief The clouds of lsrecon-compare and the benchmarks: random samples of the test shapes
/// (core/shape_corpus.h) with their ground truth.
#pragma once

#include "lsrecon/testdata/shape_corpus.h"
#include "lsrecon/testdata/simulated_scan.h"

#include <functional>
#include <string>
#include <vector>

namespace lsr::demos {

/// The draw every figure in docs/benchmarks.md was measured on.
constexpr unsigned kDefaultSeed = 2011;

struct CompareCase {
  std::string name;
  Points<3> points;        ///< what the methods see (noisy when asked)
  Points<3> normals;       ///< true outward normals at the clean positions
  std::function<double(const Vec<3>&)> sdf;  ///< the true surface's signed distance
  Points<3> truth;         ///< a dense clean sample of the true surface
  double diagonal = 1.0;   ///< bounding-box diagonal of the truth
  std::vector<int> genus;  ///< the true topology, per component
};

/// @brief points i.i.d. samples of the test shape `name` with the given variant, or its
/// simulated scan if `scanner` is given (then `points` and `variant` are not used); the seed
/// picks the draw (the same seed, the same cloud).
/// @throw lsr::InvalidInput for an unknown name.
CompareCase make_case(const std::string& name, int points, const SamplingVariant& variant, unsigned seed = kDefaultSeed,
                      const ScannerSettings* scanner = nullptr);

/// @brief The names make_case() knows.
std::vector<std::string> case_names();

}  // namespace lsr::demos
