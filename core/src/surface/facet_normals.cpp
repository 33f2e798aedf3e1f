// SPDX-License-Identifier: BSD-3-Clause
/// @file facet_normals.cpp
#include "surface/facet_normals.h"

namespace lsr {

template <int D>
Vec<D> facet_area_normal(const Points<D>& x, const std::array<Index, D>& f) {
  const Vec<D> t = x[std::size_t(f[1])] - x[std::size_t(f[0])];
  if constexpr (D == 3) {
    return t.cross(x[std::size_t(f[2])] - x[std::size_t(f[0])]);
  } else {
    return Vec<D>(t[1], -t[0]);
  }
}

template <int D>
void set_facet_normals(const LevelSetMesh<D>& surface, const std::vector<char>& flagged, Points<D>& normals) {
  Points<D> sum(surface.vertices.size(), Vec<D>::Zero());
  for (const auto& f : surface.facets) {
    const Vec<D> n = facet_area_normal<D>(surface.vertices, f);
    for (const Index v : f) sum[std::size_t(v)] += n;
  }
  for (std::size_t v = 0; v < sum.size(); ++v) {
    const bool replace = (!flagged.empty() && flagged[v]) || normals[v].dot(sum[v]) < 0.0;
    if (replace && sum[v].norm() > 0.0) normals[v] = sum[v].normalized();
  }
}

template Vec<2> facet_area_normal<2>(const Points<2>&, const std::array<Index, 2>&);
template Vec<3> facet_area_normal<3>(const Points<3>&, const std::array<Index, 3>&);
template void set_facet_normals<2>(const LevelSetMesh<2>&, const std::vector<char>&, Points<2>&);
template void set_facet_normals<3>(const LevelSetMesh<3>&, const std::vector<char>&, Points<3>&);

}  // namespace lsr
