// SPDX-License-Identifier: BSD-3-Clause
/// @file curve_refinement.cpp
#include "fit/curve_refinement.h"

#include <cmath>

namespace lsr::detail {

void refine_long_segments(LevelSetMesh<2>& curve, Points<2>& normals, const QuadricImplicit<2>& fit,
                          const std::function<double(std::size_t vertex)>& length, Points<2>& reference, int threads) {
  Points<2> added;
  std::vector<std::array<Index, 2>> facets;
  std::vector<EdgePoint> sources;
  const Index first_new = Index(curve.vertices.size());
  for (const auto& f : curve.facets) {
    const Vec<2> a = curve.vertices[std::size_t(f[0])], b = curve.vertices[std::size_t(f[1])];
    const double target = length(std::size_t(f[0]));
    const double l = (b - a).norm();
    if (!(l > 2.0 * target)) {
      facets.push_back(f);
      continue;
    }
    const int parts = int(std::ceil(l / target));
    Index previous = f[0];
    for (int k = 1; k < parts; ++k) {
      const Index v = first_new + Index(added.size());
      added.push_back(a + (double(k) / parts) * (b - a));
      const Vec<2>& ra = reference[std::size_t(f[0])];
      reference.push_back(ra + (double(k) / parts) * (reference[std::size_t(f[1])] - ra));
      sources.push_back(curve.sources[std::size_t(f[0])]);
      facets.push_back({previous, v});
      previous = v;
    }
    facets.push_back({previous, f[1]});
  }
  if (added.empty()) return;
  const Points<2> added_normals = fit.project(added, threads);
  for (std::size_t i = 0; i < added.size(); ++i) {
    curve.vertices.push_back(added[i]);
    curve.sources.push_back(sources[i]);
    normals.push_back(added_normals[i]);
  }
  curve.facets = std::move(facets);
}

}  // namespace lsr::detail
