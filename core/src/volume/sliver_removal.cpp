// SPDX-License-Identifier: BSD-3-Clause
#include "volume/sliver_removal.h"

#include "volume/simplex_angles.h"

#include <algorithm>
#include <cmath>

namespace lsr {
namespace {

constexpr double kBadAngle = kSliverAngleDegrees * kPi / 180.0;

// Box vertices on a wall of the unit box stay where they are: the box is the domain.
template <int D>
bool on_a_wall(const Vec<D>& x) {
  for (int k = 0; k < D; ++k) {
    if (x[k] <= 0.0 || x[k] >= 1.0) return true;
  }
  return false;
}

}  // namespace

template <int D>
void smooth_near_slivers(VolumeMesh<D>& m, int passes) {
  const std::size_t nv = m.vertices.size();
  std::vector<Index> offsets(nv + 1, 0), incident;
  for (const auto& s : m.simplices) {
    for (Index v : s) ++offsets[std::size_t(v) + 1];
  }
  for (std::size_t v = 1; v <= nv; ++v) offsets[v] += offsets[v - 1];
  incident.resize(std::size_t(offsets[nv]));
  std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t s = 0; s < m.simplices.size(); ++s) {
    for (Index v : m.simplices[s]) incident[std::size_t(fill[std::size_t(v)]++)] = Index(s);
  }
  auto movable = [&](Index v) { return v < m.interface_offset && !on_a_wall<D>(m.vertices[std::size_t(v)]); };
  const double small = kSmallMeasure / double(m.simplices.size());  // the box's measure is 1
  auto quality = [&](const std::array<Index, D + 1>& s) {
    return std::min(min_angle<D>(m.vertices, s), kBadAngle * signed_measure_of<D>(m.vertices, s) / small);
  };
  auto worst_around = [&](std::size_t v) {
    double w = kPi;
    for (Index k = offsets[v]; k < offsets[v + 1]; ++k) {
      w = std::min(w, quality(m.simplices[std::size_t(incident[std::size_t(k)])]));
    }
    return w;
  };
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<char> candidate(nv, 0);
    for (const auto& s : m.simplices) {
      if (quality(s) >= kBadAngle) continue;
      for (Index v : s) candidate[std::size_t(v)] = movable(v) ? 1 : 0;
    }
    for (std::size_t v = 0; v < nv; ++v) {
      if (!candidate[v]) continue;
      Vec<D> centroid = Vec<D>::Zero();
      double count = 0.0;
      for (Index k = offsets[v]; k < offsets[v + 1]; ++k) {
        for (Index w : m.simplices[std::size_t(incident[std::size_t(k)])]) {
          if (std::size_t(w) == v) continue;
          centroid += m.vertices[std::size_t(w)];
          count += 1.0;
        }
      }
      centroid /= count;
      const Vec<D> before = m.vertices[v];
      Vec<D> best = before;
      double best_quality = worst_around(v);
      for (double step : {1.0, 0.5, 0.25}) {
        m.vertices[v] = before + step * (centroid - before);
        const double q = worst_around(v);
        if (q > best_quality) {
          best_quality = q;
          best = m.vertices[v];
        }
      }
      m.vertices[v] = best;
    }
  }
}

template void smooth_near_slivers<2>(VolumeMesh<2>&, int);
template void smooth_near_slivers<3>(VolumeMesh<3>&, int);

}  // namespace lsr
