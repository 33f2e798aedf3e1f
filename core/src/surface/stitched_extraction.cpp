// SPDX-License-Identifier: BSD-3-Clause
/// @file stitched_extraction.cpp
#include "surface/stitched_extraction.h"

#include <algorithm>
#include <array>

namespace lsr {
namespace {

template <int D>
bool lexicographically_less(const Vec<D>& a, const Vec<D>& b) {
  return std::lexicographical_compare(a.data(), a.data() + D, b.data(), b.data() + D);
}

}  // namespace

template <int D>
StitchedSurface<D>::StitchedSurface(double edge_margin, int threads) : edge_margin_(edge_margin), threads_(threads) {}

template <int D>
void StitchedSurface<D>::add(const TileField<D>& tile) {
  const double margin = std::clamp(edge_margin_, 1e-9, 0.25);  // as extract_zero_level_set
  const LevelSetMesh<D> piece = extract_zero_level_set(tile.core, tile.u, edge_margin_, threads_);
  std::vector<Index> to_out(piece.vertices.size());
  for (std::size_t i = 0; i < piece.vertices.size(); ++i) {
    Index a = piece.sources[i].a, b = piece.sources[i].b;
    if (lexicographically_less<D>(tile.core.vertices[std::size_t(b)], tile.core.vertices[std::size_t(a)])) std::swap(a, b);
    const Vec<D>& xa = tile.core.vertices[std::size_t(a)];
    const Vec<D>& xb = tile.core.vertices[std::size_t(b)];
    EdgeKey key;
    std::copy_n(xa.data(), D, key.begin());
    std::copy_n(xb.data(), D, key.begin() + D);
    const auto [at, fresh] = welded_.try_emplace(key, Index(out_.vertices.size()));
    if (fresh) {
      const double ua = tile.u[std::size_t(a)], ub = tile.u[std::size_t(b)];
      const double t = std::clamp(ua / (ua - ub), margin, 1.0 - margin);  // opposite signs
      out_.vertices.push_back((1.0 - t) * xa + t * xb);
    }
    to_out[i] = at->second;
  }
  for (auto f : piece.facets) {
    for (Index& v : f) v = to_out[std::size_t(v)];
    out_.facets.push_back(f);
  }
}

template <int D>
LevelSetMesh<D> stitched_zero_level_set(const std::vector<TileField<D>>& tiles, double edge_margin, int threads) {
  StitchedSurface<D> stitched(edge_margin, threads);
  for (const TileField<D>& tile : tiles) stitched.add(tile);
  return stitched.take();
}

template class StitchedSurface<2>;
template class StitchedSurface<3>;
template LevelSetMesh<2> stitched_zero_level_set<2>(const std::vector<TileField<2>>&, double, int);
template LevelSetMesh<3> stitched_zero_level_set<3>(const std::vector<TileField<3>>&, double, int);

}  // namespace lsr
