// SPDX-License-Identifier: BSD-3-Clause
/// @file embedded_moves.cpp
#include "surface/embedded_moves.h"

#include "geometry/self_intersections.h"
#include "surface/facet_normals.h"

#include <algorithm>

namespace lsr::detail {
namespace {

// Each round keeps 3/4 of a move that still intersects: a shortened move loses at most a
// quarter more than it had to (docs/how-it-works.md, Embedded output). After 17 rounds what is
// left is under 1/128 of the move (0.75^17 = 0.0075), finer than the extraction places vertices
// (1% of their edge from its ends, closed_surface.h): then all the way back.
constexpr double kKept = 0.75;
constexpr int kRounds = 17;

}  // namespace

template <int D>
std::vector<char> keep_embedded(LevelSetMesh<D>& surface, Points<D> embedded, bool float_grid, Points<D>& normals, int threads) {
  Points<D>& x = surface.vertices;
  if (float_grid) {
    for (auto& p : x) p = rounded_to_float(p);
    for (auto& p : embedded) p = rounded_to_float(p);
  }
  const Points<D> target = x;
  std::vector<double> share(x.size(), 1.0);  // of its move each vertex keeps
  std::vector<char> shortened(x.size(), 0), among(surface.facets.size(), 0);
  for (std::size_t f = 0; f < surface.facets.size(); ++f) {
    for (Index v : surface.facets[f]) among[f] = among[f] || x[std::size_t(v)] != embedded[std::size_t(v)];
  }
  if (std::find(among.begin(), among.end(), char(1)) == among.end()) return shortened;
  const SelfIntersections<D> intersections(surface.facets, embedded, target);
  for (int round = 0;; ++round) {
    std::vector<char> back(x.size(), 0);
    bool any = false;
    for (const auto& [f, g] : intersections.pairs(x, among, threads)) {
      for (const Index h : {f, g}) {
        for (Index v : surface.facets[std::size_t(h)]) back[std::size_t(v)] = x[std::size_t(v)] != embedded[std::size_t(v)];
      }
    }
    for (std::size_t v = 0; v < x.size(); ++v) {
      if (!back[v]) continue;
      shortened[v] = 1;
      any = true;
      share[v] = round >= kRounds ? 0.0 : kKept * share[v];
      // On the segment (rounding is monotone: a rounded point between two floats stays between
      // them), within the boxes the candidates were found in.
      const Vec<D> lo = embedded[v].cwiseMin(target[v]), hi = embedded[v].cwiseMax(target[v]);
      const Vec<D> y = embedded[v] + share[v] * (target[v] - embedded[v]);
      x[v] = share[v] == 0.0 ? embedded[v] : Vec<D>((float_grid ? rounded_to_float(y) : y).cwiseMax(lo).cwiseMin(hi));
    }
    if (!any) break;  // embedded, or only pairs no move made (against the precondition)
    for (std::size_t f = 0; f < surface.facets.size(); ++f) {
      among[f] = 0;
      for (Index v : surface.facets[f]) among[f] = among[f] || back[std::size_t(v)];
    }
  }
  if (!normals.empty()) set_facet_normals(surface, shortened, normals);
  return shortened;
}

template std::vector<char> keep_embedded<2>(LevelSetMesh<2>&, Points<2>, bool, Points<2>&, int);
template std::vector<char> keep_embedded<3>(LevelSetMesh<3>&, Points<3>, bool, Points<3>&, int);

}  // namespace lsr::detail
