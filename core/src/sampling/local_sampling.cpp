// SPDX-License-Identifier: BSD-3-Clause
/// @file local_sampling.cpp
#include "sampling/local_sampling.h"

#include "sampling/isolated_points.h"
#include "sampling/spacing_over_gaps.h"
#include "sampling/tile_runs.h"
#include "thread_count.h"

#include <algorithm>
#include <cmath>

#include <omp.h>

namespace lsr {
namespace {

// Distance to the rank-th neighbour counting each position once (copies of p_i or of a
// neighbour are skipped; the farthest found if fewer).
template <int D>
double kth_distinct_distance(const Points<D>& p, const Index* nearest, int k, std::size_t i, int rank) {
  int found = 0;
  double last = 0.0;
  const Vec<D>* previous = &p[i];
  for (int j = 0; j < k; ++j) {
    const Vec<D>& q = p[nearest[j]];
    if (q == p[i] || q == *previous) continue;  // sorted by distance: copies are adjacent
    previous = &q;
    last = (q - p[i]).norm();
    if (++found == rank) break;
  }
  return last;
}

// The widest angle, around p_i in its tangent plane, free of (distinct) neighbours: about pi
// or more on the rim of a hole or at the border of a scan, where the neighbours all lie on one
// side; 2 pi / (k - 1) on average inside. In 2D: pi at the end of a curve (all on one side),
// else 0.
template <int D>
double largest_angular_gap(const Points<D>& p, const Index* nearest, int k, std::size_t i, const Vec<D>& normal,
                           Vec<D>* middle = nullptr) {
  const Eigen::Matrix<double, D, D> frame = tangent_frame(normal);
  double angle[32];
  int n = 0;
  for (int j = 0; j < k && n < 32; ++j) {
    const Vec<D> y = frame * (p[nearest[j]] - p[i]);
    if (y.template head<D - 1>().squaredNorm() == 0.0) continue;  // p_i itself, copies
    angle[n++] = D == 2 ? (y[0] > 0.0 ? 1.0 : -1.0) : std::atan2(y[1 % (D - 1)], y[0]);
  }
  if (n == 0) return 2.0 * M_PI;
  std::sort(angle, angle + n);
  if constexpr (D == 2) {
    return angle[0] == angle[n - 1] ? M_PI : 0.0;
  } else {
    double gap = angle[0] + 2.0 * M_PI - angle[n - 1], from = angle[n - 1];
    for (int j = 1; j < n; ++j) {
      if (angle[j] - angle[j - 1] > gap) {
        gap = angle[j] - angle[j - 1];
        from = angle[j - 1];
      }
    }
    if (middle) *middle = frame.transpose() * Vec<D>(std::cos(from + 0.5 * gap), std::sin(from + 0.5 * gap), 0.0);
    return gap;
  }
}

// The mean |cos| between p_i's normal and its neighbours': about 1 on a smooth surface, less
// across a crease or around a knife edge.
template <int D>
double mean_agreement(const Points<D>& normals, const Index* nearest, int k, std::size_t i) {
  double sum = 0.0;
  for (int j = 0; j < k; ++j) sum += std::abs(normals[i].dot(normals[std::size_t(nearest[j])]));
  return sum / k;
}

// The least mean |cos| between a rim point's normal and its neighbours': kRimSmoothness, less
// what noise sigma scatters PCA normals by. A normal fitted to k points over a disc of radius
// r tilts by about sigma / (r sqrt(k) / 2) per axis, so two of them differ by E[theta^2] ~
// 16 sigma^2 / (k r^2) and 1 - |cos| by half that: 0.19 (sigma / s)^2 with r^2 ~ (16 / 6) s^2.
// The allowance is calibrated (docs/calibration.md). sigma / s is the cloud's median: a crease
// inflates the local PCA "noise" as much as noise does, and scanner noise is a property of
// the scan.
template <int D>
double rim_smoothness(const LocalSampling<D>& sampling, const TileRuns& tiles) {
  std::vector<double> ratio2(sampling.noise.size());
  for (std::size_t i = tiles.first(); i < tiles.end(); ++i) {
    ratio2[i] = std::pow(sampling.noise[i] / std::max(sampling.spacing[i], 1e-300), 2);
  }
  return LocalSampling<D>::kRimSmoothness - 0.6 * tiles.median(ratio2);
}

// Of the open points (kRimGap free among their k nearest: a superset, as fewer neighbours
// leave wider gaps), those whose kRimNeighbours nearest also leave kRimGap free, whose
// neighbours' normals agree, and which have D - 1 more such points among their k nearest.
// Among 31 random neighbours the largest gap exceeds 120 degrees at 31 (2/3)^30 = 1.6e-4 of
// the points inside a surface; a point within about a spacing of a hole's edge sees the hole
// wider than that. A knife edge looks open too (its disc runs on past the edge); and a rim
// runs on through each of its points, where the rare wide gaps inside are scattered.
template <int D>
std::vector<char> confirmed_rims(const NearestPointIndex<D>& data, const std::vector<char>& open,
                                 const LocalSampling<D>& sampling, const LargeVector<Index>& neighbours, int k,
                                 int threads, const TileRuns& tiles) {
  const Points<D>& p = data.points();
  const Points<D>& normals = sampling.normals;
  std::vector<char> wide(p.size(), 0);
  constexpr int kw = LocalSampling<D>::kRimNeighbours;
  for (std::size_t tile = 0; tile + 1 < tiles.cuts.size(); ++tile) {
    Points<D> candidates;
    std::vector<std::size_t> which;
    for (std::size_t i = tiles.cuts[tile]; i < tiles.cuts[tile + 1]; ++i) {
      if (!open[i]) continue;
      candidates.push_back(p[i]);
      which.push_back(i);
    }
    LargeVector<Index> nearest;
    data.query_k(candidates, kw, nearest, threads);
    const long n = long(which.size());
    // The open side must be empty beyond the neighbourhood too: a point one neighbourhood radius
    // r into it, along the middle of the gap, at least r / 2 from the data (about r inside a hole
    // of radius >= r; a wide gap among random samples closes within about a spacing).
    Points<D> inside(which.size());
    std::vector<double> radius(which.size(), 0.0), bound(which.size()), empty;
    std::vector<Index> found;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long c = 0; c < n; ++c) {
      const std::size_t i = which[std::size_t(c)];
      const Index* near = &nearest[std::size_t(c) * kw];
      Vec<D> middle = Vec<D>::Zero();
      wide[i] = largest_angular_gap(p, near, kw, i, normals[i], &middle) > LocalSampling<D>::kRimGap;
      radius[c] = (p[near[kw - 1]] - p[i]).norm();
      inside[c] = p[i] + radius[c] * middle;
      bound[c] = 0.5 * radius[c];
    }
    data.query_within(inside, bound, empty, found, threads);
    for (long c = 0; c < n; ++c) {
      if (found[std::size_t(c)] >= 0) wide[which[std::size_t(c)]] = 0;
    }
  }
  tiles.share(wide);
  std::vector<char> rim(p.size(), 0);
  const double smoothness = rim_smoothness(sampling, tiles);
  for (std::size_t i = tiles.first(); i < tiles.end(); ++i) {
    const Index* around = &neighbours[(i - tiles.first()) * std::size_t(k)];
    if (!wide[i] || mean_agreement(normals, around, k, i) < smoothness) continue;
    int others = 0;
    for (int j = 0; j < k; ++j) others += std::size_t(around[j]) != i && wide[std::size_t(around[j])];
    rim[i] = others >= D - 1;
  }
  tiles.share(rim);
  return rim;
}

}  // namespace

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

template <int D>
LocalSampling<D> estimate_local_sampling(const NearestPointIndex<D>& data, int threads, HeightFieldsAt height_fields,
                                         const Progress& progress, const SamplingTiles& tiling, ScanLines scan_lines,
                                         double isolated_factor) {
  constexpr int k = LocalSampling<D>::kNeighbours;
  const int t = detail::thread_count(threads);
  const Points<D>& p = data.points();
  const TileRuns tiles(p.size(), tiling);
  const std::size_t first = tiles.first();
  LocalSampling<D> s;
  LargeVector<Index> neighbours;  // of this worker's points, k each
  {
    Points<D> copy;
    data.query_k(run_of(p, first, tiles.end(), copy), k, neighbours, t);
  }
  progress.update("sampling", -1.0);
  const long n = long(tiles.end() - first);
  std::vector<double> spacing(p.size()), noise(p.size()), elongation(p.size());
  const bool rims = height_fields == HeightFieldsAt::rims || height_fields == HeightFieldsAt::all_and_rims;
  const bool all = height_fields == HeightFieldsAt::all || height_fields == HeightFieldsAt::all_and_rims;
  std::vector<char> open(rims ? p.size() : 0, 0);
  s.normals.resize(p.size());
  s.gap.resize(p.size());
#pragma omp parallel for schedule(static) num_threads(t)
  for (long r = 0; r < n; ++r) {
    const std::size_t i = first + std::size_t(r);
    const Index* nearest = &neighbours[std::size_t(r) * k];
    spacing[i] = kth_distinct_distance(p, nearest, k, i, LocalSampling<D>::kSpacingRank);
    s.gap[i] = kth_distinct_distance(p, nearest, k, i, 1);
    pca(p, nearest, k, noise[i], s.normals[i], &elongation[i]);
    if (rims) open[i] = largest_angular_gap(p, nearest, k, i, s.normals[i]) > LocalSampling<D>::kRimGap;
  }
  tiles.share(spacing);
  tiles.share(noise);
  neighbourhood_medians(spacing, neighbours, k, first, s.spacing, t);
  neighbourhood_medians(noise, neighbours, k, first, s.noise, t);
  progress.update("sampling", -1.0);
  const bool raised = spacing_over_gaps(data, elongation, s, t, tiles, scan_lines);
  if constexpr (D == 3) s.scan_lines = raised;
  if (isolated_factor > 0.0 && isolated_points_found(data, neighbours, raised, isolated_factor, t, tiles, s)) {
    s.stopped_at_isolated = true;
    return s;
  }
  if (raised) raise_spacing_over_gaps(data, neighbours, t, s, progress, tiles);
  tiles.share(s.spacing);
  tiles.share(s.noise);
  tiles.share(s.normals);
  tiles.share(s.gap);
  if (rims) s.rim = confirmed_rims(data, open, s, neighbours, k, t, tiles);
  progress.update("sampling", -1.0);
  // 48 bytes a point in 3D: not even allocated for a closed cloud without rims.
  if (all || (rims && tiles.sum(long(std::count(s.rim.begin() + long(first), s.rim.begin() + long(tiles.end()), 1))) > 0)) {
    s.height_fields.resize(p.size());
#pragma omp parallel for schedule(dynamic, 1024) num_threads(t)
    for (long r = 0; r < n; ++r) {
      const std::size_t i = first + std::size_t(r);
      if (all || s.rim[i]) s.height_fields[i] = fit_height_field(p, &neighbours[std::size_t(r) * k], k, p[i], s.normals[i], (p[std::size_t(neighbours[std::size_t(r) * k + k - 1])] - p[i]).norm());
    }
    tiles.share(s.height_fields);
  }
  return s;
}

template LocalSampling<2> estimate_local_sampling<2>(const NearestPointIndex<2>&, int, HeightFieldsAt, const Progress&, const SamplingTiles&, ScanLines, double);
template LocalSampling<3> estimate_local_sampling<3>(const NearestPointIndex<3>&, int, HeightFieldsAt, const Progress&, const SamplingTiles&, ScanLines, double);

}  // namespace lsr
