// SPDX-License-Identifier: BSD-3-Clause
/// @file fitted_field.cpp
#include "fit/fitted_field.h"

#include "fit/merge_without_joins.h"
#include "fit/sheet_gaps.h"
#include "surface/closed_surface.h"

#include <algorithm>
#include <cmath>

namespace lsr::detail {

namespace {

// The vertices within band_factor local scales of the front (in `fitted`, all when empty).
template <int D>
struct Band {
  Points<D> points;
  std::vector<Index> vertices;
  std::vector<double> fit;  ///< F at points
};

// F in the band where it is trusted, u elsewhere, into values (and fit_share near an opening).
// Returns, per band slot, whether F cuts a bridge between facing sheets there.
template <int D>
std::vector<char> blend_in_band(const FrontToFit<D>& front, const Band<D>& band, std::vector<double>& values,
                                std::vector<double>& fit_share) {
  // kHandover: where unsupported solid starts going to the front (below).
  constexpr double kHandover = 1.0;
  const Eigen::VectorXd &u = front.u, &scale = front.scale, &distance = front.distance;
  const std::vector<char>& near_opening = front.near_opening;
  const double trust_factor = front.trust_factor;
  const std::vector<double>& fv = band.fit;
  const std::vector<Index>& band_vertices = band.vertices;
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
  for (std::size_t k = 0; k < band_vertices.size(); ++k) {
    const Index v = band_vertices[k];
    if (!(u[v] < 0.0 && fv[k] >= 0.0)) continue;
    disputed.push_back(k);
    queries.push_back(band.points[k]);
    query_distance.push_back(distance[v]);
    query_scale.push_back(scale[v]);
  }
  const std::vector<char> in_gap = between_facing_sheets(front.data, front.normals, queries, query_distance, query_scale, front.threads);
  std::vector<char> cuts_bridge(band_vertices.size(), 0);
  for (std::size_t i = 0; i < disputed.size(); ++i) cuts_bridge[disputed[i]] = in_gap[i];
  for (std::size_t k = 0; k < band_vertices.size(); ++k) {
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
    const bool hole = !front.over_hole.empty() && front.over_hole[std::size_t(v)];
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
  return cuts_bridge;
}

// The front's topology kept where the fit would join (merge_without_joins), then the voids
// cut off filled and the specks absorbed.
template <int D>
void keep_the_fronts_joins(const FrontToFit<D>& front, const Band<D>& band, const std::vector<char>& cuts_bridge,
                           std::vector<double>& values) {
  const SimplexMesh<D>& mesh = front.mesh;
  const Eigen::VectorXd &u = front.u, &scale = front.scale, &distance = front.distance;
  // The fit moves the surface and may remove what the front got wrong (bridges across a neck it
  // had not cut, handles of a noisy front), but not join what the front kept apart: where the two
  // sides of a thin part or a crease lie within a fit's neighbourhood, its rounding opens handles.
  // Far from the data (past the largest empty disc, as above) the front is held by curvature
  // alone and a guess: there the fit may join too (a coarse front spans a ring's hole). Not over
  // a spanned hole, where the rims' discs hold the front where the samples say the surface goes.
  // A void the merge cut off the outside bounds no data and is filled. Bubbles and specks
  // narrower than a spacing go last.
  Eigen::VectorXd capped = u;
  cap_at_walls<D>(mesh, capped);
  cap_at_walls<D>(mesh, values);
  // In a gap between facing sheets the data's normals on both sides say outside, so the fit may
  // open it even where that joins: the front stalls short in a slit 3-4 spacings wide and its
  // pins hold a membrane across it.
  std::vector<char> may_join(values.size());
  for (std::size_t v = 0; v < values.size(); ++v) {
    const bool over_hole = !front.over_hole.empty() && front.over_hole[v];
    may_join[v] = !over_hole && distance[Eigen::Index(v)] > kUnsupported * scale[Eigen::Index(v)];
  }
  for (std::size_t k = 0; k < cuts_bridge.size(); ++k) {
    if (cuts_bridge[k]) may_join[std::size_t(band.vertices[k])] = 1;
  }
  merge_without_joins<D>(mesh, capped, values, may_join);
  fill_cut_off_voids<D>(mesh, capped, values);
  absorb_small_parts<D>(mesh, front.neighbours, scale, values);
}

}  // namespace

template <int D>
FittedField fitted_field(const FrontToFit<D>& front, const QuadricImplicit<D>& fit, const std::vector<char>& fitted) {
  constexpr double band_factor = 3.0;
  const Eigen::VectorXd &u = front.u, &scale = front.scale;
  FittedField f{std::vector<double>(u.data(), u.data() + u.size()), {}};
  Band<D> band;
  for (Eigen::Index v = 0; v < u.size(); ++v) {
    if (std::abs(u[v]) < band_factor * scale[v] && (fitted.empty() || fitted[std::size_t(v)])) {
      band.points.push_back(front.mesh.vertices[v]);
      band.vertices.push_back(Index(v));
    }
  }
  fit.evaluate(band.points, band.fit, nullptr, front.threads);
  // Near a sealed opening, the share of F in values: the output is projected onto F only that
  // far (below), as F extrapolates where the front took over (projected in full, a front's cap
  // over an open end turns facets inside out). Elsewhere in full: F is the accurate surface.
  if (!front.near_opening.empty()) {
    f.fit_share.resize(f.values.size());
    for (std::size_t v = 0; v < f.values.size(); ++v) f.fit_share[v] = front.near_opening[v] ? 0.0 : 1.0;
  }
  const std::vector<char> cuts_bridge = blend_in_band(front, band, f.values, f.fit_share);
  keep_the_fronts_joins(front, band, cuts_bridge, f.values);
  return f;
}

template FittedField fitted_field<2>(const FrontToFit<2>&, const QuadricImplicit<2>&, const std::vector<char>&);
template FittedField fitted_field<3>(const FrontToFit<3>&, const QuadricImplicit<3>&, const std::vector<char>&);

}  // namespace lsr::detail
