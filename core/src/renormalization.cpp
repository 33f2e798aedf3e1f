// SPDX-License-Identifier: BSD-3-Clause
/// @file renormalization.cpp
#include "lsrecon/core/renormalization.h"

#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/nearest_point_index.h"
#include "lsrecon/core/point_simplex_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <omp.h>

namespace lsr {
namespace {

// Candidates per vertex: the facets with the k nearest centroids. Facets near a vertex of a
// conforming front are of similar size, so the closest facet is among them.
constexpr int kCandidates2D = 8;
constexpr int kCandidates3D = 8;

template <int D>
double facet_distance(const LevelSetMesh<D>& front, Index f, const Vec<D>& p) {
  const auto& v = front.facets[f];
  if constexpr (D == 2) {
    return segment_distance(p, front.vertices[v[0]], front.vertices[v[1]]);
  } else {
    return triangle_distance(p, front.vertices[v[0]], front.vertices[v[1]], front.vertices[v[2]]);
  }
}

}  // namespace

template <int D>
RenormalizationReport<D> renormalize(const SimplexMesh<D>& mesh, Eigen::VectorXd& u,
                                  const Eigen::VectorXd& gradient_norm, double band, int threads) {
  RenormalizationReport<D> report;
  const std::vector<double> values(u.data(), u.data() + u.size());
  report.front = extract_zero_level_set(mesh, values);
  const LevelSetMesh<D>& front = report.front;
  if (front.facets.empty()) return report;

  Points<D> centroids(front.facets.size());
  for (std::size_t f = 0; f < front.facets.size(); ++f) {
    Vec<D> c = Vec<D>::Zero();
    for (Index v : front.facets[f]) c += front.vertices[v];
    centroids[f] = c / double(D);
  }
  const NearestPointIndex<D> index(std::move(centroids));

  // |u| / |grad u| is the first-order distance to the zero set; 2 * band leaves room for its
  // error.
  std::vector<Index> near;
  Points<D> queries;
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    if (std::abs(u[i]) < 2.0 * band * std::max(gradient_norm[i], 1e-12)) {
      near.push_back(Index(i));
      queries.push_back(mesh.vertices[i]);
    }
  }
  const int k = D == 2 ? kCandidates2D : kCandidates3D;
  std::vector<Index> candidates;
  index.query_k(queries, k, candidates, threads);
  std::vector<double> distance(near.size());
  const long n = long(near.size());
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (long q = 0; q < n; ++q) {
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < k; ++j) {
      best = std::min(best, facet_distance(front, candidates[std::size_t(q) * k + j], queries[q]));
    }
    distance[q] = best;
  }

  Eigen::VectorXd renormalized = u.unaryExpr([band](double x) { return x < 0.0 ? -band : band; });
  for (std::size_t q = 0; q < near.size(); ++q) {
    const double d = std::min(distance[q], band);
    renormalized[near[q]] = u[near[q]] < 0.0 ? -d : d;
  }
  u = std::move(renormalized);
  report.band_vertices = Index(std::count_if(distance.begin(), distance.end(),
                                             [band](double d) { return d < band; }));
  return report;
}

template RenormalizationReport<2> renormalize<2>(const SimplexMesh<2>&, Eigen::VectorXd&,
                                                   const Eigen::VectorXd&, double, int);
template RenormalizationReport<3> renormalize<3>(const SimplexMesh<3>&, Eigen::VectorXd&,
                                                   const Eigen::VectorXd&, double, int);

}  // namespace lsr
