// SPDX-License-Identifier: BSD-3-Clause
/// @file fitted_surface.cpp
#include "fit/fitted_surface.h"

#include "surface/closed_surface.h"

#include "fit/curve_refinement.h"
#include "fit/merge_without_joins.h"
#include "fit/rim_normals.h"
#include "fit/sheet_gaps.h"
#include "fit/surface_refinement.h"
#include "mesh/data_metric.h"
#include "sampling/residual_noise.h"
#include "surface/facet_normals.h"
#include "surface/rim_curvature_closure.h"
#include "surface/unsupported_fairing.h"

#include <algorithm>

namespace lsr::detail {

namespace {

// Past the largest empty disc among random samples (1.45 local scales, local_sampling.h) no
// sample supports the surface: there the fit extrapolates and the front is held by curvature
// alone (so attach_fit's merge may join there too).
constexpr double kUnsupported = 1.5;

// At the rim of the unsupported surface (its fixed vertices next to a free one) the fit's
// normals lean towards the flattened part: from above, 10-15 degrees on average on the sphere's
// and the linked rings' rims, which the balance of rim_curvature_closure.h turns into a mean
// curvature 0.8x the tube's. A quadric height field over the rim vertex's nearest data, wide
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
// carried parts of it through the data (measured with a support radius of one scale:
// hippo1's back showed through its body). The set grows from the vertices past 1.5 scales
// over the surface's edges through those past half a scale (hysteresis): the rims of unseen
// parts are moved with them, down to the last seen rows of a tube's underside (from above,
// the linked rings' flattened tube bottoms lay 2.5-3.6 spacings from the data, mostly within
// 1.5 scales), while a vertex in a gap of a well sampled surface, with no vertex past 1.5
// scales near, is left alone (all vertices past one scale: clean i.i.d. Hausdorff 1.63x).
template <int D>
std::vector<char> fair_unsupported_parts(ReconstructionResult<D>& r, const NearestPointIndex<D>& data, const Eigen::VectorXd& scale, int threads) {
  constexpr double kStep = 4.0, kTowardsData = 0.5, kLoose = 0.5;
  LevelSetMesh<D>& s = r.surface;
  LargeVector<Index> nearest;
  data.query_k(s.vertices, 1, nearest, threads);
  std::vector<char> free(s.vertices.size()), loose(s.vertices.size());
  Points<D> towards(s.vertices.size());  // to the nearest sample
  for (std::size_t i = 0; i < free.size(); ++i) {
    const EdgePoint& e = s.sources[i];
    towards[i] = data.points()[std::size_t(nearest[i])] - s.vertices[i];
    const double away = towards[i].norm() / ((1.0 - e.t) * scale[e.a] + e.t * scale[e.b]);
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
void attach_fit(ReconstructionResult<D>& r, const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                const QuadricImplicit<D>& fit, const Eigen::VectorXd& u, const Eigen::VectorXd& scale,
                const Eigen::VectorXd& distance, double trust_factor, const std::vector<char>& over_hole,
                const std::vector<char>& near_opening, const NearestPointIndex<D>& data, const Points<D>& normals,
                bool volume, int threads) {
  // kHandover: where unsupported solid starts going to the front (below).
  constexpr double band_factor = 3.0, kHandover = 1.0;
  const auto is_over_hole = [&](std::size_t v) { return !over_hole.empty() && over_hole[v]; };
  std::vector<double> values(u.data(), u.data() + u.size());
  Points<D> band;
  std::vector<Index> band_vertices;
  for (Eigen::Index v = 0; v < u.size(); ++v) {
    if (std::abs(u[v]) < band_factor * scale[v]) {
      band.push_back(mesh.vertices[v]);
      band_vertices.push_back(Index(v));
    }
  }
  std::vector<double> f;
  fit.evaluate(band, f, nullptr, threads);
  // Near a sealed opening, the share of F in values: the output is projected onto F only that
  // far (below), as F extrapolates where the front took over (measured: projected in full, the
  // front's cap over a tube's open end turned facets inside out). Elsewhere in full (measured:
  // limited everywhere, the clean sphere's Hausdorff distance x3.9).
  std::vector<double> fit_share;
  if (!near_opening.empty()) {
    fit_share.resize(values.size());
    for (std::size_t v = 0; v < values.size(); ++v) fit_share[v] = near_opening[v] ? 0.0 : 1.0;
  }
  auto limit_share = [&](Index v, double share) {
    if (!fit_share.empty() && near_opening[std::size_t(v)]) fit_share[std::size_t(v)] *= share;
  };
  // The settled front lies within gap_factor spacings of the data: a fit that disagrees with its
  // sign farther away than that is a failed local fit (creases, sparse spots), not the surface.
  // But in a gap between two facing sheets (sheet_gaps.h) the pinned cells of both sides hold a
  // bridge of front as deep as half the gap, which the fit cuts at any depth (measured: a bridge
  // 2.09 spacings deep kept the noisy, holey two spheres of seed 3 in one piece).
  std::vector<std::size_t> disputed;  // band slots where the fit says outside, inside the front
  Points<D> queries;
  std::vector<double> query_distance, query_scale;
  for (std::size_t k = 0; k < band.size(); ++k) {
    const Index v = band_vertices[k];
    if (!(u[v] < 0.0 && f[k] >= 0.0)) continue;
    disputed.push_back(k);
    queries.push_back(band[k]);
    query_distance.push_back(distance[v]);
    query_scale.push_back(scale[v]);
  }
  const std::vector<char> in_gap = between_facing_sheets(data, normals, queries, query_distance, query_scale, threads);
  std::vector<char> cuts_bridge(band.size(), 0);
  for (std::size_t i = 0; i < disputed.size(); ++i) cuts_bridge[disputed[i]] = in_gap[i];
  for (std::size_t k = 0; k < band.size(); ++k) {
    const Index v = band_vertices[k];
    const bool trusted = (f[k] < 0.0) == (u[v] < 0.0) || std::abs(u[v]) < trust_factor * scale[v] || cuts_bridge[k];
    values[v] = trusted ? f[k] : u[v];
    if (!fit_share.empty() && near_opening[std::size_t(v)]) fit_share[std::size_t(v)] = trusted ? 1.0 : 0.0;
    auto hand_over = [&](double start) {
      const double w = std::clamp((distance[v] - start * scale[v]) / scale[v], 0.0, 1.0);
      values[v] = (1.0 - w) * values[v] + w * u[v];
      limit_share(v, 1.0 - w);
    };
    // Over a spanned hole nothing pins the front, and on a mesh the vertices next to the discs
    // keep a distance up to half an edge, through which a long run lets it creep into the solid
    // (measured: 0.13 into a sphere by step 26 of the holey two spheres, with a small handle in
    // its zero set, on 5 of 80 draws of the holey clouds). Where the fit adds solid there and
    // the front near v (u away) lies beyond the data's gap, the fit's solid stays. Not where
    // the front is at the data: a knife edge's rim discs run on past its tip, and so do the
    // fit's tangent planes (measured: without that test, fins 2.8 spacings past the 5k bunny's
    // ear tips).
    const bool adds_solid = values[v] < 0.0 && u[v] > 0.0;
    const bool hole = is_over_hole(std::size_t(v));
    if (hole && adds_solid && distance[v] - u[v] > trust_factor * scale[v]) continue;
    // Solid the fit adds outside the front must be near the data: the surface between random
    // samples lies within about 1.45 spacings of one (the largest empty disc, local_sampling.h),
    // and farther than one spacing from every sample on exp(-6) = 0.25% of its area. Where the
    // fit's surface passes farther from the data (nearer to v than half v's distance to the
    // data), it extrapolates: the tangent planes of a knife edge's sides run on past its tip
    // (measured on the bunny's ear). From 1 to 2 spacings the front takes over (measured: from
    // 1.5 to 2.5, the noisy bunny kept fins on its ear tips, Hausdorff distance up to 1.9e-2 of
    // the diagonal, 2.8x Poisson's with the true normals). A pit of the front deep inside the
    // data is left to the fit (there |F| is v's distance to the data: measured, the noisy two
    // spheres got a void). Near a sealed opening (a tube's open end, where the front closes
    // what the fits continue) the fit's distance is not asked: on the tube's axis past its end
    // the fits' surface lies a tube radius away, nearer than half the distance to the rim
    // (measured: a notched end, the tube's wall run on past the front's cap).
    if (adds_solid && (-values[v] < 0.5 * distance[v] || (!near_opening.empty() && near_opening[std::size_t(v)]))) {
      hand_over(kHandover);
    }
    // Over a spanned hole (where the rims' discs are nearer than the points) the front lies on
    // the discs, where the fit only extrapolates: from the gap to one spacing beyond it the
    // front takes over, gradually, so that the two zero sets join without a step (measured:
    // switching opened small handles at holes). Elsewhere only unsupported solid (above) is
    // handed over (measured: a handover wherever the fit is far from the data left the noisy
    // two spheres a third component in their neck).
    if (hole) hand_over(trust_factor);
  }
  // The fit moves the surface and may remove what the front got wrong (bridges across a neck it
  // had not cut, handles of a noisy front), but not join what the front kept apart: where the two
  // sides of a thin part or a crease lie within a fit's neighbourhood, its rounding opens handles
  // (measured: the cup with the 10x density gradient and the holey double torus got one each).
  // Far from the data (past the largest empty disc, as above) the front is held by curvature
  // alone and a guess: there the fit may join too (measured: a coarse front spanned a torus's
  // hole). Not over a spanned hole, where the rims' discs hold the front where the samples say
  // the surface goes (measured: the fit opened a handle across a hole on the noisy, holey
  // limb's thin part, seed 2, where the front had none). A void the merge cut off the outside
  // bounds no data and is filled (measured: with the fit's solid kept over every hole the front
  // had crept through, one 2 spacings wide inside the holey limb). Bubbles and specks narrower
  // than a spacing go last (measured: a one-vertex void in the noisy, holey limb and one in the
  // cup's wall).
  Eigen::VectorXd front = u;
  cap_at_walls<D>(mesh, front);
  cap_at_walls<D>(mesh, values);
  // In a gap between facing sheets the data's normals on both sides say outside, so the fit may
  // open it even where that joins: the front stalls short in a slit 3-4 spacings wide and its
  // pins hold a membrane across it (measured: the scanned triple torus's middle hole, genus 2).
  std::vector<char> may_join(values.size());
  for (std::size_t v = 0; v < values.size(); ++v) {
    may_join[v] = !is_over_hole(v) && distance[Eigen::Index(v)] > kUnsupported * scale[Eigen::Index(v)];
  }
  for (std::size_t i = 0; i < disputed.size(); ++i) {
    if (in_gap[i]) may_join[std::size_t(band_vertices[disputed[i]])] = 1;
  }
  merge_without_joins<D>(mesh, front, values, may_join);
  fill_cut_off_voids<D>(mesh, front, values);
  absorb_small_parts<D>(mesh, neighbours, scale, values);
  r.surface = extract_closed_surface(mesh, data.points(), values, threads);
  const Points<D> extracted = fit_share.empty() ? Points<D>() : r.surface.vertices;
  r.normals = fit.project(r.surface.vertices, threads);
  for (std::size_t i = 0; i < extracted.size(); ++i) {
    const EdgePoint& e = r.surface.sources[i];
    const double share = (1.0 - e.t) * fit_share[std::size_t(e.a)] + e.t * fit_share[std::size_t(e.b)];
    if (share < 1.0) r.surface.vertices[i] = extracted[i] + share * (r.surface.vertices[i] - extracted[i]);
  }
  set_facet_normals(r.surface, fair_unsupported_parts(r, data, scale, threads), r.normals);
  attach_volume(r, mesh, values, volume);
}

template <int D>
void refine_onto_fit(ReconstructionResult<D>& r, const QuadricImplicit<D>& fit, const Eigen::VectorXd& scale, const Eigen::VectorXd& distance,
                     int threads) {
  // Facets longer than 2 l are split: in 3D, l = half a size gives fewer triangles than an
  // isotropic mesh's extraction and a smaller Chamfer distance (measured: the sphere, torus and
  // trefoil at 20k points: 0.75 sizes gave 2-3x the isotropic mesh's Chamfer distance). Past
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
    refine_long_segments(r.surface, r.normals, fit, length, threads);
  } else {
    refine_long_edges(r.surface, r.normals, fit, length, threads);
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

template void refine_onto_fit<2>(ReconstructionResult<2>&, const QuadricImplicit<2>&, const Eigen::VectorXd&, const Eigen::VectorXd&, int);
template void refine_onto_fit<3>(ReconstructionResult<3>&, const QuadricImplicit<3>&, const Eigen::VectorXd&, const Eigen::VectorXd&, int);
template QuadricImplicit<2> fit_quadrics<2>(const NearestPointIndex<2>&, const Points<2>&, const std::vector<double>&, int,
                                            const Progress&);
template QuadricImplicit<3> fit_quadrics<3>(const NearestPointIndex<3>&, const Points<3>&, const std::vector<double>&, int,
                                            const Progress&);
template void attach_fit<2>(ReconstructionResult<2>& r, const SimplexMesh<2>& mesh, const VertexNeighbours& neighbours,
                const QuadricImplicit<2>& fit, const Eigen::VectorXd& u, const Eigen::VectorXd& scale,
                const Eigen::VectorXd& distance, double trust_factor, const std::vector<char>& over_hole,
                const std::vector<char>& near_opening, const NearestPointIndex<2>& data, const Points<2>& normals,
                bool volume, int threads);
template void attach_fit<3>(ReconstructionResult<3>& r, const SimplexMesh<3>& mesh, const VertexNeighbours& neighbours,
                const QuadricImplicit<3>& fit, const Eigen::VectorXd& u, const Eigen::VectorXd& scale,
                const Eigen::VectorXd& distance, double trust_factor, const std::vector<char>& over_hole,
                const std::vector<char>& near_opening, const NearestPointIndex<3>& data, const Points<3>& normals,
                bool volume, int threads);

}  // namespace lsr::detail
