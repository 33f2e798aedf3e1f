// SPDX-License-Identifier: BSD-3-Clause
/// @file vertices_near.cpp
#include "mesh/vertices_near.h"

#include "geometry/nearest_point_index.h"

namespace lsr::detail {

template <int D>
std::vector<char> near_any(const Points<D>& vertices, const std::vector<char>& seed, double radius, int threads) {
  Points<D> seeds;
  for (std::size_t v = 0; v < seed.size(); ++v) {
    if (seed[v]) seeds.push_back(vertices[v]);
  }
  std::vector<char> out(vertices.size(), 0);
  if (seeds.empty()) return out;
  const NearestPointIndex<D> index(std::move(seeds));
  std::vector<double> dist;
  index.query(vertices, dist, nullptr, threads);
  for (std::size_t v = 0; v < vertices.size(); ++v) out[v] = dist[v] <= radius;
  return out;
}

template std::vector<char> near_any<2>(const Points<2>& vertices, const std::vector<char>& seed, double radius, int threads);
template std::vector<char> near_any<3>(const Points<3>& vertices, const std::vector<char>& seed, double radius, int threads);

}  // namespace lsr::detail
