// SPDX-License-Identifier: BSD-3-Clause
/// @file renormalization.cpp
#include "lsrecon/core/renormalization.h"

#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/nearest_point_index.h"

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

double segment_distance(const Vec<2>& p, const Vec<2>& a, const Vec<2>& b) {
  const Vec<2> ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Closest point on triangle abc by Voronoi regions (Ericson, Real-Time Collision Detection 5.1.5).
double triangle_distance(const Vec<3>& p, const Vec<3>& a, const Vec<3>& b, const Vec<3>& c) {
  const Vec<3> ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Vec<3> bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vec<3> cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

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
