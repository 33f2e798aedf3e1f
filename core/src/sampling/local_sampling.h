// SPDX-License-Identifier: BSD-3-Clause
/// @file local_sampling.h
/// @brief Per-point sampling scales of an unoriented point set: the local spacing (the gap the
/// front must not fall through), the local noise and the PCA normal. Every length the solver
/// derives (mesh size, pin radius, curvature weight, stopping tolerance) is a multiple of them.
///
/// Spacing rule. For points sampled on a curve (2D) or surface (3D), spacing_i is the distance
/// from p_i to its k-th distinct neighbour with k = 2 in 2D and k = 6 in 3D: the number of
/// nearest neighbours of a regular sampling (two along a curve, six on a hexagonal patch), so a
/// lattice or an evenly spaced curve gives exactly its sampling gap. For i.i.d. samples of
/// density rho on a surface, the 6-th neighbour distance is about sqrt(6 / (pi rho)), and a disc
/// of radius c spacing is empty with probability exp(-6 c^2): the largest empty disc among
/// 2e5 random points has c ~ 1.45, while the nearest-neighbour distance (0.5 / sqrt(rho)) is
/// 2.8x smaller than the spacing. The raw values are median-filtered over the neighbourhood so
/// that one isolated or clustered point does not set its own scale. On a curve random gaps are
/// far wider (the largest of n about ln n mean gaps): there the spacing is at least the
/// half-width of the widest gap between neighbours over kHoleToSpacing (local_sampling.cpp).
#pragma once

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/progress.h"
#include "lsrecon/core/reconstruction_options.h"
#include "lsrecon/core/tile_exchange.h"
#include "sampling/cloud_halo.h"

#include <array>
#include <vector>

namespace lsr {

/// @brief Rows: D-1 unit tangents, then the normal; a fixed function of the normal.
template <int D>
Eigen::Matrix<double, D, D> tangent_frame(const Vec<D>& normal);

/// @brief h(x) = c + g.x + x^T A x / 2 over the tangent coordinates x of a point's frame
/// (tangent_frame of its normal, origin at the point), fitted to its neighbours.
template <int D>
struct HeightField {
  static constexpr int kTerms = 1 + (D - 1) + D * (D - 1) / 2;
  std::array<double, kTerms> coefficients{};  ///< c, g, then A's upper triangle (a, b, c: x^2/2, xy, y^2/2)
  static Eigen::Matrix<double, kTerms, 1> monomials(const Eigen::Matrix<double, D - 1, 1>& x);
  double height(const Eigen::Matrix<double, D - 1, 1>& x) const;
  Eigen::Matrix<double, D - 1, 1> slope(const Eigen::Matrix<double, D - 1, 1>& x) const;  ///< grad h
  /// largest |eigenvalue| of A (noise of deviation sigma adds about 2 sigma / r^2 over a
  /// neighbourhood of radius r)
  double largest_curvature() const;
};

/// @brief PCA of the k points `nearest` of p: the unit normal (least spread), the thickness (the
/// deviation along it) and, if asked, the elongation (second largest spread over the largest).
template <int D>
void pca(const Points<D>& p, const Index* nearest, int k, double& thickness, Vec<D>& normal, double* elongation = nullptr);

/// @brief The HeightField fitted by least squares to the k points `nearest` of p over the
/// tangent_frame of `normal` with its origin at `origin` (zero if degenerate: duplicates,
/// colinear points); `radius`, the neighbourhood's, scales the normal equations.
template <int D>
HeightField<D> fit_height_field(const Points<D>& p, const Index* nearest, int k, const Vec<D>& origin, const Vec<D>& normal,
                                double radius);

/// @brief Sampling scales per data point (all #N, lengths in the points' units).
template <int D>
struct LocalSampling {
  std::vector<double> spacing;  ///< k-th distinct neighbour distance, median-filtered
  std::vector<double> noise;    ///< sqrt of the smallest PCA eigenvalue of the neighbourhood, median-filtered
  Points<D> normals;            ///< unit PCA normal of the neighbourhood, unoriented
  /// quadric height field of the neighbourhood in the PCA frame (least squares, the point
  /// itself included): where the surface goes beyond the neighbourhood, e.g. across a hole.
  /// Empty unless asked for (and, at the rims, unless there is one); zero where not asked for.
  std::vector<HeightField<D>> height_fields;
  std::vector<double> gap;      ///< distance to the nearest distinct neighbour, raw (not filtered)
  /// 1 where the kRimNeighbours nearest leave an angle wider than kRimGap free around the point
  /// in its tangent plane, the data stays away from a point one neighbourhood radius r into the
  /// middle of that gap (farther than r / 2), the part is smooth (kRimSmoothness), and D - 1 more
  /// such points lie among its kNeighbours nearest: the rim of a sampling hole or of an open
  /// scan. Empty unless height fields are asked for at the rims.
  std::vector<char> rim;
  bool scan_lines = false;  ///< 3D: read as scan lines (below)
  /// estimate_local_sampling, given an isolated_factor, found isolated points and stopped: only
  /// `spacing` and `gap` are set, for drop_isolated (the sampling is then estimated without them)
  bool stopped_at_isolated = false;
  static constexpr double kRimGap = 2.09;  ///< radians (120 degrees); pi on a straight rim
  static constexpr int kRimNeighbours = 32;
  /// mean |cos| of the angles between a rim point's normal and its neighbours' at least
  /// (18 degrees on average; calibrated, docs/calibration.md); less
  /// an allowance for the noise's scatter of the normals, 0.6 (sigma / s)^2 with the cloud's
  /// median sigma / s (local_sampling.cpp)
  static constexpr double kRimSmoothness = 0.95;
  static constexpr int kNeighbours = 16;  ///< neighbourhood size, the point itself included
  static constexpr int kSpacingRank = D == 2 ? 2 : 6;  ///< k of the spacing rule
  /// 3D scan lines (local_sampling.cpp): a cloud whose median elongation is below this is read
  /// as scan lines; its normals and noise then come from kHoleNeighbours neighbours, and its
  /// spacing is at least the radius of the largest empty disc among them over kHoleToSpacing
  static constexpr double kScanLineElongation = 0.4;
  /// ... or when more than this fraction of its points have a normal of their kNeighbours
  /// nearest more than 45 degrees from that of their kHoleNeighbours nearest: dense scan lines
  /// whose noise hides their elongation (local_sampling.cpp)
  static constexpr double kScanLineDisagreement = 0.1;
  static constexpr int kHoleNeighbours = 32;
  static constexpr double kHoleToSpacing = 0.55;
};

/// @brief Where estimate_local_sampling fits height fields (and whether it finds the rims).
enum class HeightFieldsAt {
  none,
  rims,           ///< at the rims it finds
  all,            ///< at every point; no rims looked for
  all_and_rims    ///< at every point, and the rims found
};

/// @brief Which points this worker estimates, and how it shares them (tile_exchange.h).
struct SamplingTiles {
  int tiles = 1;                    ///< runs along the points' order
  const CloudHalo* halo = nullptr;  ///< the index holds this worker's run and its halo; null: every point, one process
};

/// @brief Estimates the sampling scales of every point of the index (with a halo: of the run's
/// points, whose neighbourhoods the halo holds). Exact duplicates are skipped when ranking
/// neighbours. Deterministic for any thread count, tiling and number of workers: each worker
/// computes its own points and exchanges the values the others' halos read.
/// @param threads 0 for all cores
/// @param height_fields where to fit height_fields (only spanning holes needs them; at every
/// point they took 0.24 s of the 0.54 s of the sampling stage on a 200k-point torus)
/// @param progress stage "sampling", fraction unknown, between the passes over the points
/// (each up to a minute at 10M points); throws Cancelled
/// @param scan_lines 3D: whether to read the cloud as scan lines, automatic: decide from it
/// @param isolated_factor > 0: stop as soon as any point is found isolated by drop_isolated's
/// rule with this factor (isolated_points.h; LocalSampling::stopped_at_isolated)
template <int D>
LocalSampling<D> estimate_local_sampling(const NearestPointIndex<D>& data, int threads = 0,
                                         HeightFieldsAt height_fields = HeightFieldsAt::none,
                                         const Progress& progress = Progress(), const SamplingTiles& tiles = {},
                                         ScanLines scan_lines = ScanLines::automatic, double isolated_factor = 0.0);

/// @brief The median of values (copied; empty gives 0).
double median(std::vector<double> values);

}  // namespace lsr
