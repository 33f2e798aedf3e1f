// SPDX-License-Identifier: BSD-3-Clause
/// @file spacing_over_gaps.cpp
#include "sampling/spacing_over_gaps.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <omp.h>

namespace lsr {
namespace {

// The radius of the largest disc in p_i's tangent plane free of its k neighbours (projected),
// among discs centred within half the neighbourhood's radius of p_i (where the neighbours
// surround the centre, so the disc is a hole in the sample, not the neighbourhood's edge):
// candidate centres on 16 rays at a quarter and half that radius.
template <int D>
double empty_disc_radius(const Points<D>& p, const Index* nearest, int k, std::size_t i, const Vec<D>& normal) {
  const Eigen::Matrix<double, D, D> frame = tangent_frame(normal);
  Eigen::Matrix<double, D - 1, 1> y[64];
  double radius = 0.0;
  for (int j = 0; j < k && j < 64; ++j) {
    y[j] = (frame * (p[nearest[j]] - p[i])).template head<D - 1>();
    radius = std::max(radius, y[j].norm());
  }
  double largest = 0.0;
  for (int a = 0; a < 16; ++a) {
    for (const double t : {0.25, 0.5}) {
      Eigen::Matrix<double, D - 1, 1> c = Eigen::Matrix<double, D - 1, 1>::Zero();
      c[0] = t * radius * std::cos(a * M_PI / 8);
      if constexpr (D == 3) c[1] = t * radius * std::sin(a * M_PI / 8);
      double nearest_distance = std::numeric_limits<double>::infinity();
      for (int j = 0; j < k && j < 64; ++j) nearest_distance = std::min(nearest_distance, (y[j] - c).norm());
      largest = std::max(largest, nearest_distance);
    }
  }
  return largest;
}

// Scan lines: the k nearest of a point lie along its own line, 3-10 times nearer than the
// next line (CGAL's raw scans and the simulated ones). Their spacing is the line's, and their
// PCA normal is any direction across the line. A cloud is taken as scan lines when its median
// elongation (spread across the line over spread along it, of the kNeighbours nearest) is below
// kScanLineElongation (calibrated, docs/calibration.md). Then
// normals and noise come from kHoleNeighbours, which reach the next lines, and the spacing is at
// least the radius of the largest empty disc among them (median-filtered) over
// kHoleToSpacing. i.i.d. samples are left as they were.
//
// Denser lines hide their elongation in their noise: when the range noise exceeds the spacing
// along a line, the k nearest are a noisy piece of one line, spread along it and along the
// normal, and their PCA normal lies across the line in the tangent plane. Such a cloud shows
// itself by its narrow and wide normals disagreeing (more than 45 degrees apart at a share of
// its points well above the i.i.d. samples' and the single views');
// above kScanLineDisagreement the cloud is read as scan lines too. Checked on every 8th point.
template <int D>
bool normals_disagree(const NearestPointIndex<D>& data, const LocalSampling<D>& s, int threads, const TileRuns& tiles) {
  constexpr int wide = LocalSampling<D>::kHoleNeighbours;
  constexpr std::size_t kStride = 8;
  const Points<D>& p = data.points();
  Points<D> probes;
  std::vector<std::size_t> which;
  for (std::size_t i = tiles.first(); i < tiles.end(); ++i) {
    if (tiles.global(i) % kStride != 0) continue;
    probes.push_back(p[i]);
    which.push_back(i);
  }
  LargeVector<Index> nearest;
  data.query_k(probes, wide, nearest, threads);
  const long n = long(probes.size());
  long disagree = 0;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(+ : disagree)
  for (long j = 0; j < n; ++j) {
    double thickness = 0.0;
    Vec<D> normal;
    pca(p, &nearest[std::size_t(j) * wide], wide, thickness, normal);
    if (std::abs(normal.dot(s.normals[which[std::size_t(j)]])) < std::sqrt(0.5)) ++disagree;
  }
  const std::size_t probed = (tiles.global_size(p.size()) + kStride - 1) / kStride;
  return double(tiles.sum(disagree)) > LocalSampling<D>::kScanLineDisagreement * double(probed);
}

// Calls at(i, its kHoleNeighbours nearest) for each of this worker's points, holding one tile's
// neighbour lists at a time.
template <int D, class AtPoint>
void over_wide_neighbourhoods(const NearestPointIndex<D>& data, int threads, const Progress& progress, const TileRuns& tiles,
                              const AtPoint& at) {
  constexpr int wide = LocalSampling<D>::kHoleNeighbours;
  const Points<D>& p = data.points();
  for (std::size_t tile = 0; tile + 1 < tiles.cuts.size(); ++tile) {
    progress.update("sampling", -1.0);
    const std::size_t first = tiles.cuts[tile];
    Points<D> copy;
    LargeVector<Index> nearest;
    data.query_k(run_of(p, first, tiles.cuts[tile + 1], copy), wide, nearest, threads);
    const long n = long(tiles.cuts[tile + 1] - first);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long r = 0; r < n; ++r) at(first + std::size_t(r), &nearest[std::size_t(r) * wide]);
  }
}

// On a curve (2D) the gaps between random samples are exponential: the largest of n is about
// ln n mean gaps (6.5, 7.9 and 10.4 among 300, 1500 and 10000 on a circle), 6.5-13 times the
// spacing at its ends, and the front fell through them (a random circle came out as 18-362
// loops). So the spacing is at least the half-width of the widest gap between consecutive
// neighbours along the tangent (of the kHoleNeighbours nearest; its middle within half their
// radius of the point, where they surround it) over kHoleToSpacing, median-filtered: the rule of
// 3D scan lines, whose empty disc becomes a gap between two samples, so that a hole's rim (all
// its neighbours on one side) is not widened. Evenly spaced samples keep their spacing: a gap
// a gives 0.91 a, and the spacing rule a.
double widest_gap_between(const Points<2>& p, const Index* nearest, int k, std::size_t i, const Vec<2>& normal) {
  const Vec<2> tangent(-normal.y(), normal.x());
  double t[LocalSampling<2>::kHoleNeighbours];
  double radius = 0.0;
  for (int j = 0; j < k; ++j) {
    t[j] = tangent.dot(p[nearest[j]] - p[i]);
    radius = std::max(radius, std::abs(t[j]));
  }
  std::sort(t, t + k);
  double widest = 0.0;
  for (int j = 1; j < k; ++j) {
    if (std::abs(t[j] + t[j - 1]) <= radius) widest = std::max(widest, t[j] - t[j - 1]);
  }
  return widest;
}

}  // namespace

double neighbourhood_median(const std::vector<double>& raw, const Index* nearest, int k) {
  double v[32];
  for (int j = 0; j < k; ++j) v[j] = raw[std::size_t(nearest[j])];
  std::nth_element(v, v + k / 2, v + k);
  return v[k / 2];
}

void neighbourhood_medians(const std::vector<double>& raw, const LargeVector<Index>& nearest, int k, std::size_t first,
                           std::vector<double>& out, int threads) {
  out.resize(raw.size());
  const long n = long(nearest.size() / std::size_t(k));
#pragma omp parallel for schedule(static) num_threads(threads)
  for (long r = 0; r < n; ++r) out[first + std::size_t(r)] = neighbourhood_median(raw, &nearest[std::size_t(r) * k], k);
}

template <int D>
bool spacing_over_gaps(const NearestPointIndex<D>& data, const std::vector<double>& elongation, const LocalSampling<D>& s,
                       int threads, const TileRuns& tiles, ScanLines mode) {
  if (tiles.global_size(data.points().size()) < std::size_t(LocalSampling<D>::kHoleNeighbours)) return false;
  if constexpr (D == 2) {
    return true;
  } else {
    if (mode != ScanLines::automatic) return mode == ScanLines::yes;
    return tiles.median(elongation) < LocalSampling<D>::kScanLineElongation || normals_disagree(data, s, threads, tiles);
  }
}

template <int D>
double gap_width(const Points<D>& p, const Index* around, std::size_t i, Vec<D>& normal, double& noise) {
  constexpr int wide = LocalSampling<D>::kHoleNeighbours;
  if constexpr (D == 3) {
    pca(p, around, wide, noise, normal);
    return empty_disc_radius(p, around, wide, i, normal);
  } else {
    (void)noise;
    return 0.5 * widest_gap_between(p, around, wide, i, normal);
  }
}

template <int D>
void raise_spacing_over_gaps(const NearestPointIndex<D>& data, const LargeVector<Index>& neighbours, int threads,
                             LocalSampling<D>& s, const Progress& progress, const TileRuns& tiles) {
  constexpr int k = LocalSampling<D>::kNeighbours;
  const Points<D>& p = data.points();
  std::vector<double> width(p.size()), noise(D == 3 ? p.size() : 0);
  over_wide_neighbourhoods(data, threads, progress, tiles, [&](std::size_t i, const Index* around) {
    double thickness = 0.0;
    width[i] = gap_width(p, around, i, s.normals[i], thickness);
    if constexpr (D == 3) noise[i] = thickness;
  });
  progress.update("sampling", -1.0);
  if constexpr (D == 3) {
    tiles.share(noise);
    neighbourhood_medians(noise, neighbours, k, tiles.first(), s.noise, threads);
  }
  tiles.share(width);
  std::vector<double> filtered;
  neighbourhood_medians(width, neighbours, k, tiles.first(), filtered, threads);
  for (std::size_t i = tiles.first(); i < tiles.end(); ++i) {
    s.spacing[i] = std::max(s.spacing[i], filtered[i] / LocalSampling<D>::kHoleToSpacing);
  }
}

template bool spacing_over_gaps<2>(const NearestPointIndex<2>&, const std::vector<double>&, const LocalSampling<2>&, int, const TileRuns&, ScanLines);
template double gap_width<2>(const Points<2>&, const Index*, std::size_t, Vec<2>&, double&);
template void raise_spacing_over_gaps<2>(const NearestPointIndex<2>&, const LargeVector<Index>&, int, LocalSampling<2>&, const Progress&, const TileRuns&);
template bool spacing_over_gaps<3>(const NearestPointIndex<3>&, const std::vector<double>&, const LocalSampling<3>&, int, const TileRuns&, ScanLines);
template double gap_width<3>(const Points<3>&, const Index*, std::size_t, Vec<3>&, double&);
template void raise_spacing_over_gaps<3>(const NearestPointIndex<3>&, const LargeVector<Index>&, int, LocalSampling<3>&, const Progress&, const TileRuns&);

}  // namespace lsr
