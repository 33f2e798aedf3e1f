// SPDX-License-Identifier: BSD-3-Clause
/// @file surface_refinement.cpp
#include "fit/surface_refinement.h"

#include <algorithm>
#include <utility>

namespace lsr::detail {
namespace {

// Bisections in a row: each halves the longest edges, so ten passes shorten them 1000x, far
// more than the anisotropic sizes' ratio.
constexpr int kMaxPasses = 10;

// Facet f cut at the midpoints m of its split edges (-1: not split) into `out`: four facets
// with three, two with one, and with two the corner triangle and the quadrilateral left,
// cut along its shorter diagonal (`at`: a vertex's position).
template <class At>
void split_facet(const std::array<Index, 3>& f, const std::array<Index, 3>& m, const At& at, std::vector<std::array<Index, 3>>& out) {
  const int split = int(m[0] >= 0) + int(m[1] >= 0) + int(m[2] >= 0);
  if (split == 0) {
    out.push_back(f);
    return;
  }
  if (split == 3) {
    out.push_back({f[0], m[0], m[2]});
    out.push_back({m[0], f[1], m[1]});
    out.push_back({m[2], m[1], f[2]});
    out.push_back({m[0], m[1], m[2]});
    return;
  }
  // Turned so that edge 0 (v0 v1) is split and, with two split, edge 1 too.
  int r = 0;
  while (!(m[std::size_t(r)] >= 0 && (split == 1 || m[std::size_t((r + 1) % 3)] >= 0))) ++r;
  const Index v0 = f[std::size_t(r)], v1 = f[std::size_t((r + 1) % 3)], v2 = f[std::size_t((r + 2) % 3)];
  const Index m01 = m[std::size_t(r)];
  if (split == 1) {
    out.push_back({v0, m01, v2});
    out.push_back({m01, v1, v2});
    return;
  }
  const Index m12 = m[std::size_t((r + 1) % 3)];
  out.push_back({m01, v1, m12});
  if ((at(v0) - at(m12)).squaredNorm() <= (at(m01) - at(v2)).squaredNorm()) {
    out.push_back({v0, m01, m12});
    out.push_back({v0, m12, v2});
  } else {
    out.push_back({v0, m01, v2});
    out.push_back({m01, m12, v2});
  }
}

}  // namespace

void refine_long_edges(LevelSetMesh<3>& surface, Points<3>& normals, const QuadricImplicit<3>& fit,
                       const std::function<double(std::size_t vertex)>& length, Points<3>& reference, int threads) {
  std::vector<double> limit(surface.vertices.size());
  for (std::size_t v = 0; v < limit.size(); ++v) limit[v] = 2.0 * length(v);
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    // The long edges, each once, and the midpoint vertex each gets.
    std::vector<std::pair<Index, Index>> long_edges;
    for (const auto& f : surface.facets) {
      for (std::size_t i = 0; i < 3; ++i) {
        const Index a = f[i], b = f[(i + 1) % 3];
        const double l = (surface.vertices[std::size_t(b)] - surface.vertices[std::size_t(a)]).norm();
        if (a < b && l > std::min(limit[std::size_t(a)], limit[std::size_t(b)])) long_edges.emplace_back(a, b);
      }
    }
    if (long_edges.empty()) return;
    std::sort(long_edges.begin(), long_edges.end());
    long_edges.erase(std::unique(long_edges.begin(), long_edges.end()), long_edges.end());
    const Index first_new = Index(surface.vertices.size());
    Points<3> added(long_edges.size());
    for (std::size_t k = 0; k < long_edges.size(); ++k) {
      const auto [a, b] = long_edges[k];
      added[k] = 0.5 * (surface.vertices[std::size_t(a)] + surface.vertices[std::size_t(b)]);
      reference.push_back(0.5 * (reference[std::size_t(a)] + reference[std::size_t(b)]));
      surface.sources.push_back(surface.sources[std::size_t(a)]);
      limit.push_back(std::min(limit[std::size_t(a)], limit[std::size_t(b)]));
    }
    const auto midpoint = [&](Index a, Index b) -> Index {
      const auto e = std::minmax(a, b);
      const auto it = std::lower_bound(long_edges.begin(), long_edges.end(), std::make_pair(e.first, e.second));
      return it != long_edges.end() && *it == std::make_pair(e.first, e.second) ? first_new + Index(it - long_edges.begin()) : -1;
    };
    const auto at = [&](Index v) -> Vec<3> {
      return v >= first_new ? added[std::size_t(v - first_new)] : Vec<3>(surface.vertices[std::size_t(v)]);
    };
    std::vector<std::array<Index, 3>> facets;
    facets.reserve(surface.facets.size() * 2);
    for (const auto& f : surface.facets) split_facet(f, {midpoint(f[0], f[1]), midpoint(f[1], f[2]), midpoint(f[2], f[0])}, at, facets);
    const Points<3> midpoints = added;
    Points<3> added_normals = fit.project(added, threads);
    for (std::size_t k = 0; k < added.size(); ++k) {
      // A chord's midpoint lies within kappa L^2 / 8 of a smooth surface: a projection farther
      // than a quarter of the edge went to another part of the fit (where the front, not the
      // fit, placed the surface: over open sides and holes), and the midpoint stays.
      const auto [a, b] = long_edges[k];
      const double l = (surface.vertices[std::size_t(b)] - surface.vertices[std::size_t(a)]).norm();
      if ((added[k] - midpoints[k]).norm() > 0.25 * l) {
        added[k] = midpoints[k];
        added_normals[k] = (normals[std::size_t(a)] + normals[std::size_t(b)]).normalized();
      }
    }
    surface.vertices.insert(surface.vertices.end(), added.begin(), added.end());
    normals.insert(normals.end(), added_normals.begin(), added_normals.end());
    surface.facets = std::move(facets);
  }
}

}  // namespace lsr::detail
