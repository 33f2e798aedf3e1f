// SPDX-License-Identifier: BSD-3-Clause
/// @file metric_adaptation.h
/// @brief A mesh adapted to a Riemannian metric field (paper section 6.2; issue 46, item 2) by
/// the classical local operations: long edges split, short edges collapsed, edges flipped to
/// the better shape, vertices relocated. The goal is a unit mesh: every edge of length 1 in the
/// metric, every element equilateral in it (docs/how-it-works.md, Anisotropic meshes). Vertices
/// on the faces of the mesh's bounding box stay on them, and its corners stay where they are.
/// Triangles (metric_adaptation_2d.cpp) and tetrahedra (metric_adaptation_3d.cpp).
#pragma once

#include "lsrecon/core/simplex_geometry.h"
#include "mesh/level_set_metric.h"

#include <array>
#include <functional>

namespace lsr {

/// The metric asked for at a point: evaluated once per vertex the adaptation creates.
template <int D>
using MetricField = std::function<Metric<D>(const Vec<D>&)>;

/// @brief What the adaptation did.
struct MetricAdaptationStats {
  Index splits = 0;
  Index collapses = 0;
  Index flips = 0;  ///< 2D edge flips; 3D 2-3 and 3-2 swaps
  Index moves = 0;
  int cycles = 0;  ///< rounds of split, collapse, flip and relocation
};

/// @brief Edge lengths kept in [kShortEdge, kLongEdge] in the metric: a split halves an edge of
/// length above sqrt(2) into two above 1/sqrt(2), so the two bounds do not chase each other.
inline constexpr double kLongEdge = 1.4142135623730951;
inline constexpr double kShortEdge = 0.7071067811865476;

/// @brief The length of the edge e in a metric that varies from ma at its start to mb at its
/// end, the sizes varying geometrically between them: (la - lb) / ln(la / lb), the mean of
/// la and lb where they are close.
template <int D>
double metric_length(const Vec<D>& e, const Metric<D>& ma, const Metric<D>& mb);

/// @brief The shape of a triangle in the constant metric m: 4 sqrt(3) |T|_m / sum of its squared
/// edge lengths in m; 1 for equilateral in m, 0 for flat, negative when inverted.
double metric_quality(const std::array<Vec<2>, 3>& x, const Metric<2>& m);

/// @brief The shape of a tetrahedron in m: 12 (3 |T|_m)^(2/3) / sum of its squared edge lengths
/// in m; 1 for regular in m, 0 for flat, negative when inverted.
double metric_quality(const std::array<Vec<3>, 4>& x, const Metric<3>& m);

/// @brief Adapts `mesh` (positively oriented, conforming) to `metric` in at most `max_cycles`
/// rounds, stopping once a round changes the vertex count by less than 2%. Returns a positively
/// oriented mesh whose vertices are new (mesh's positions where kept).
SimplexMesh<2> adapt_to_metric(const SimplexMesh<2>& mesh, const MetricField<2>& metric, int max_cycles = 12,
                               MetricAdaptationStats* stats = nullptr);
SimplexMesh<3> adapt_to_metric(const SimplexMesh<3>& mesh, const MetricField<3>& metric, int max_cycles = 12,
                               MetricAdaptationStats* stats = nullptr);

}  // namespace lsr
