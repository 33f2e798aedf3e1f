// SPDX-License-Identifier: BSD-3-Clause
/// @file fitted_field.cpp
#include "fit/fitted_field.h"

#include "fit/merge_without_joins.h"
#include "fit/sheet_gaps.h"
#include "surface/closed_surface.h"

#include <algorithm>
#include <cmath>

namespace lsr::detail {

template <int D>
FittedField fitted_field(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const QuadricImplicit<D>& fit,
                         const Eigen::VectorXd& u, const Eigen::VectorXd& scale, const Eigen::VectorXd& distance,
                         double trust_factor, const std::vector<char>& over_hole, const std::vector<char>& near_opening,
                         const NearestPointIndex<D>& data, const Points<D>& normals, int threads, const std::vector<char>& fitted) {
  // kHandover: where unsupported solid starts going to the front (below).
  constexpr double band_factor = 3.0, kHandover = 1.0;
  const auto is_over_hole = [&](std::size_t v) { return !over_hole.empty() && over_hole[v]; };
  FittedField f{std::vector<double>(u.data(), u.data() + u.size()), {}};
  std::vector<double>& values = f.values;
  std::vector<double>& fit_share = f.fit_share;
  Points<D> band;
  std::vector<Index> band_vertices;
  for (Eigen::Index v = 0; v < u.size(); ++v) {
    if (std::abs(u[v]) < band_factor * scale[v] && (fitted.empty() || fitted[std::size_t(v)])) {
      band.push_back(mesh.vertices[v]);
      band_vertices.push_back(Index(v));
    }
  }
  std::vector<double> fv;
  fit.evaluate(band, fv, nullptr, threads);
  // Near a sealed opening, the share of F in values: the output is projected onto F only that
  // far (below), as F extrapolates where the front took over (projected in full, a front's cap
  // over an open end turns facets inside out). Elsewhere in full: F is the accurate surface.
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
  // bridge of front as deep as half the gap, which the fit cuts at any depth.
  std::vector<std::size_t> disputed;  // band slots where the fit says outside, inside the front
  Points<D> queries;
  std::vector<double> query_distance, query_scale;
  for (std::size_t k = 0; k < band.size(); ++k) {
    const Index v = band_vertices[k];
    if (!(u[v] < 0.0 && fv[k] >= 0.0)) continue;
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
    const bool trusted = (fv[k] < 0.0) == (u[v] < 0.0) || std::abs(u[v]) < trust_factor * scale[v] || cuts_bridge[k];
    values[v] = trusted ? fv[k] : u[v];
    if (!fit_share.empty() && near_opening[std::size_t(v)]) fit_share[std::size_t(v)] = trusted ? 1.0 : 0.0;
    auto hand_over = [&](double start) {
      const double w = std::clamp((distance[v] - start * scale[v]) / scale[v], 0.0, 1.0);
      values[v] = (1.0 - w) * values[v] + w * u[v];
      limit_share(v, 1.0 - w);
    };
    // Over a spanned hole nothing pins the front, and on a mesh the vertices next to the discs
    // keep a distance up to half an edge, through which a long run lets it creep into the solid.
    // Where the fit adds solid there and the front near v (u away) lies beyond the data's gap,
    // the fit's solid stays. Not where the front is at the data: a knife edge's rim discs run on
    // past its tip, and so do the fit's tangent planes (fins).
    const bool adds_solid = values[v] < 0.0 && u[v] > 0.0;
    const bool hole = is_over_hole(std::size_t(v));
    if (hole && adds_solid && distance[v] - u[v] > trust_factor * scale[v]) continue;
    // Solid the fit adds outside the front must be near the data: the surface between random
    // samples lies within about 1.45 spacings of one (the largest empty disc, local_sampling.h),
    // and farther than one spacing from every sample on exp(-6) = 0.25% of its area. Where the
    // fit's surface passes farther from the data (nearer to v than half v's distance to the
    // data), it extrapolates: the tangent planes of a knife edge's sides run on past its tip.
    // From 1 to 2 spacings (kHandover, calibrated) the front takes over. A
    // pit of the front deep inside the data is left to the fit (there |F| is v's distance to
    // the data). Near a sealed opening (a tube's open end, where the front closes what the fits
    // continue) the fit's distance is not asked: on the tube's axis past its end the fits'
    // surface lies a tube radius away, nearer than half the distance to the rim.
    if (adds_solid && (-values[v] < 0.5 * distance[v] || (!near_opening.empty() && near_opening[std::size_t(v)]))) {
      hand_over(kHandover);
    }
    // Over a spanned hole (where the rims' discs are nearer than the points) the front lies on
    // the discs, where the fit only extrapolates: from the gap to one spacing beyond it the
    // front takes over, gradually, so that the two zero sets join without a step (a switch
    // opens small handles). Elsewhere only unsupported solid (above) is handed over: a handover
    // wherever the fit is far from the data splits necks.
    if (hole) hand_over(trust_factor);
  }
  // The fit moves the surface and may remove what the front got wrong (bridges across a neck it
  // had not cut, handles of a noisy front), but not join what the front kept apart: where the two
  // sides of a thin part or a crease lie within a fit's neighbourhood, its rounding opens handles.
  // Far from the data (past the largest empty disc, as above) the front is held by curvature
  // alone and a guess: there the fit may join too (a coarse front spans a ring's hole). Not over
  // a spanned hole, where the rims' discs hold the front where the samples say the surface goes.
  // A void the merge cut off the outside bounds no data and is filled. Bubbles and specks
  // narrower than a spacing go last.
  Eigen::VectorXd front = u;
  cap_at_walls<D>(mesh, front);
  cap_at_walls<D>(mesh, values);
  // In a gap between facing sheets the data's normals on both sides say outside, so the fit may
  // open it even where that joins: the front stalls short in a slit 3-4 spacings wide and its
  // pins hold a membrane across it.
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
  return f;
}

template FittedField fitted_field<2>(const SimplexMesh<2>&, const VertexNeighbours&, const QuadricImplicit<2>&, const Eigen::VectorXd&,
                                      const Eigen::VectorXd&, const Eigen::VectorXd&, double, const std::vector<char>&,
                                      const std::vector<char>&, const NearestPointIndex<2>&, const Points<2>&, int,
                                      const std::vector<char>&);
template FittedField fitted_field<3>(const SimplexMesh<3>&, const VertexNeighbours&, const QuadricImplicit<3>&, const Eigen::VectorXd&,
                                      const Eigen::VectorXd&, const Eigen::VectorXd&, double, const std::vector<char>&,
                                      const std::vector<char>&, const NearestPointIndex<3>&, const Points<3>&, int,
                                      const std::vector<char>&);

}  // namespace lsr::detail
