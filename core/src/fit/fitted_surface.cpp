// SPDX-License-Identifier: BSD-3-Clause
/// @file fitted_surface.cpp
#include "fit/fitted_surface.h"

#include "surface/closed_surface.h"

#include "fit/curve_refinement.h"
#include "fit/fitted_field.h"
#include "fit/rim_normals.h"
#include "fit/surface_refinement.h"
#include "mesh/data_metric.h"
#include "sampling/residual_noise.h"
#include "surface/facet_normals.h"
#include "surface/rim_curvature_closure.h"
#include "surface/unsupported_fairing.h"

#include <algorithm>

namespace lsr::detail {

namespace {

// At the rim of the unsupported surface (its fixed vertices next to a free one) the fit's
// normals lean towards the flattened part, which the balance of rim_curvature_closure.h would
// turn into too small a mean curvature. A quadric height field over the rim vertex's nearest data, wide
// enough to span several scan rows, extrapolates within 1-3 degrees (rim_normals.h).
template <int D>
void take_rim_normals_from_data(const LevelSetMesh<D>& s, const EdgeGraph& edges, const std::vector<char>& free,
                                const NearestPointIndex<D>& data, Points<D>& normals, int threads) {
  std::vector<std::size_t> rim;
  Points<D> at;
  for (std::size_t v = 0; v < free.size(); ++v) {
    if (free[v]) continue;
    for (std::size_t k = edges.first[v]; k < edges.first[v + 1]; ++k) {
      if (!free[std::size_t(edges.next[k])]) continue;
      rim.push_back(v);
      at.push_back(s.vertices[v]);
      break;
    }
  }
  const Points<D> n = rim_normals(data, at, threads);
  for (std::size_t i = 0; i < rim.size(); ++i) {
    Vec<D>& to = normals[rim[i]];
    if (n[i].squaredNorm() > 0.0) to = n[i].dot(to) < 0.0 ? Vec<D>(-n[i]) : n[i];
  }
}

// The unsupported surface (over unseen sides, holes, cavities seen at grazing angles) is faired
// (unsupported_fairing.h) and rounded to the curvature of its rim (rim_curvature_closure.h);
// returns the vertices moved (empty: none), which take their facets' normals (the fit's there
// belong to another sheet). A moved vertex comes towards its nearest sample by half its
// distance at most: a single view's back lies 1-2 scales behind its front, and the fairing
// carried parts of it through the data. The set grows from the vertices past 1.5 scales over
// the surface's edges through those past half a scale (hysteresis, calibrated): the rims of
// unseen parts are moved with them, down to the last seen rows of a tube's underside, while a
// vertex in a gap of a well sampled surface, with no vertex past 1.5 scales near, is left alone.
template <int D>
std::vector<char> fair_unsupported_parts(ReconstructionResult<D>& r, const NearestPointIndex<D>& data, const std::vector<double>& scale, int threads) {
  constexpr double kStep = 4.0, kTowardsData = 0.5, kLoose = 0.5;
  LevelSetMesh<D>& s = r.surface;
  LargeVector<Index> nearest;
  data.query_k(s.vertices, 1, nearest, threads);
  std::vector<char> free(s.vertices.size()), loose(s.vertices.size());
  Points<D> towards(s.vertices.size());  // to the nearest sample
  for (std::size_t i = 0; i < free.size(); ++i) {
    towards[i] = data.points()[std::size_t(nearest[i])] - s.vertices[i];
    const double away = towards[i].norm() / scale[i];
    free[i] = away > kUnsupported;
    loose[i] = away > kLoose;
  }
  if (std::find(free.begin(), free.end(), 1) == free.end()) return {};
  const EdgeGraph edges = edge_graph(s);
  grow_over_edges(edges, free, loose);
  const Points<D> before = s.vertices;
  if (fair_unsupported(s, edges, free, kStep) == 0) return {};
  Points<D> oriented = r.normals;  // the fit's, but where they point against the facets
  set_facet_normals(s, {}, oriented);
  take_rim_normals_from_data(s, edges, free, data, oriented, threads);
  round_to_rim_curvature(s, edges, free, oriented);
  for (std::size_t i = 0; i < free.size(); ++i) {
    if (!free[i]) continue;
    const double away = towards[i].norm(), closer = (s.vertices[i] - before[i]).dot(towards[i]) / away;
    if (closer > kTowardsData * away) s.vertices[i] -= (closer - kTowardsData * away) / away * towards[i];
  }
  return free;
}

}  // namespace

template <int D>
void project_onto_fit(ReconstructionResult<D>& r, const QuadricImplicit<D>& fit, const std::vector<double>& share,
                      const std::vector<double>& vertex_scale, const NearestPointIndex<D>& data, int threads) {
  const Points<D> extracted = share.empty() ? Points<D>() : r.surface.vertices;
  r.normals = fit.project(r.surface.vertices, threads);
  for (std::size_t i = 0; i < extracted.size(); ++i) {
    if (share[i] < 1.0) r.surface.vertices[i] = extracted[i] + share[i] * (r.surface.vertices[i] - extracted[i]);
  }
  set_facet_normals(r.surface, fair_unsupported_parts(r, data, vertex_scale, threads), r.normals);
}

template <int D>
Points<D> attach_fit(ReconstructionResult<D>& r, const FrontToFit<D>& front, const QuadricImplicit<D>& fit, bool volume) {
  const Eigen::VectorXd& scale = front.scale;
  const int threads = front.threads;
  FittedField f = fitted_field(front, fit);
  r.surface = extract_closed_surface(front.mesh, front.data.points(), f.values, threads);
  std::vector<double> share, vertex_scale(r.surface.vertices.size());
  for (std::size_t i = 0; i < vertex_scale.size(); ++i) {
    const EdgePoint& e = r.surface.sources[i];
    vertex_scale[i] = (1.0 - e.t) * scale[e.a] + e.t * scale[e.b];
    if (!f.fit_share.empty()) share.push_back((1.0 - e.t) * f.fit_share[std::size_t(e.a)] + e.t * f.fit_share[std::size_t(e.b)]);
  }
  const Points<D> extracted = r.surface.vertices;
  project_onto_fit(r, fit, share, vertex_scale, front.data, threads);
  attach_volume(r, front.mesh, f.values, volume);
  return extracted;
}

template <int D>
void refine_onto_fit(ReconstructionResult<D>& r, const QuadricImplicit<D>& fit, const Eigen::VectorXd& scale, const Eigen::VectorXd& distance,
                     Points<D>& embedded, int threads) {
  // Facets longer than 2 l are split: in 3D, l = half a size gives fewer triangles than an
  // isotropic mesh's extraction and a smaller Chamfer distance (calibrated). Past
  // the band where the mesh is anisotropic (data_metric.h), over holes and open sides, the size
  // grows as the mesh's does across (MetricSizes::growth), as an isotropic mesh's would.
  const double share = D == 2 ? 0.75 : 0.5, growth = 0.5, band = kAnisotropicReach<D>;
  const auto length = [&](std::size_t i) {
    const EdgePoint& e = r.surface.sources[i];
    const auto at = [&](const Eigen::VectorXd& f) { return (1.0 - e.t) * f[e.a] + e.t * f[e.b]; };
    const double past = at(distance) - band * at(scale);
    return share * (at(scale) + (past > 0.0 ? growth * past : 0.0));
  };
  if constexpr (D == 2) {
    refine_long_segments(r.surface, r.normals, fit, length, embedded, threads);
  } else {
    refine_long_edges(r.surface, r.normals, fit, length, embedded, threads);
  }
}

template <int D>
QuadricImplicit<D> fit_quadrics(const NearestPointIndex<D>& data, const Points<D>& normals, const std::vector<double>& point_scale,
                                int threads, const Progress& progress) {
  // Both read the same neighbours (freed before the blends).
  const int k = std::min<int>(QuadricImplicit<D>::kFitNeighbours, int(data.points().size()));
  LargeVector<Index> nearest;
  data.query_k(data.points(), k, nearest, threads);
  const std::vector<double> fit_noise = residual_noise(data.points(), normals, nearest, k, threads);
  return QuadricImplicit<D>(data, normals, point_scale, fit_noise, threads, &nearest, progress);
}

template void project_onto_fit<2>(ReconstructionResult<2>&, const QuadricImplicit<2>&, const std::vector<double>&, const std::vector<double>&,
                                  const NearestPointIndex<2>&, int);
template void refine_onto_fit<2>(ReconstructionResult<2>&, const QuadricImplicit<2>&, const Eigen::VectorXd&, const Eigen::VectorXd&,
                                 Points<2>&, int);
template void project_onto_fit<3>(ReconstructionResult<3>&, const QuadricImplicit<3>&, const std::vector<double>&, const std::vector<double>&,
                                  const NearestPointIndex<3>&, int);
template void refine_onto_fit<3>(ReconstructionResult<3>&, const QuadricImplicit<3>&, const Eigen::VectorXd&, const Eigen::VectorXd&,
                                 Points<3>&, int);
template QuadricImplicit<2> fit_quadrics<2>(const NearestPointIndex<2>&, const Points<2>&, const std::vector<double>&, int,
                                            const Progress&);
template QuadricImplicit<3> fit_quadrics<3>(const NearestPointIndex<3>&, const Points<3>&, const std::vector<double>&, int,
                                            const Progress&);
template Points<2> attach_fit<2>(ReconstructionResult<2>&, const FrontToFit<2>&, const QuadricImplicit<2>&, bool);
template Points<3> attach_fit<3>(ReconstructionResult<3>&, const FrontToFit<3>&, const QuadricImplicit<3>&, bool);

}  // namespace lsr::detail
