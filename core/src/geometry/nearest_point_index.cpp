// SPDX-License-Identifier: BSD-3-Clause
/// @file nearest_point_index.cpp
/// @brief FLANN single kd-tree with unlimited checks: exact nearest neighbours.
#include "geometry/nearest_point_index.h"

#include "lsrecon/core/errors.h"
#include "sampling/point_validation.h"
#include "sampling/z_order.h"
#include "thread_count.h"

#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <omp.h>

namespace lsr {

template <int D>
struct NearestPointIndex<D>::Impl {
  Points<D> points;
  std::vector<double> flat;  // FLANN reads row-major coordinates and does not copy them
  std::unique_ptr<flann::KDTreeSingleIndex<flann::L2<double>>> index;
};

namespace {

// The nearest point closer than a bound: FLANN prunes every subtree farther than the bound
// from the start, instead of from the first leaf it reaches.
struct BoundedNearest : flann::ResultSet<double> {
  explicit BoundedNearest(double bound_squared) : worst(bound_squared) {}
  bool full() const override { return true; }
  void addPoint(double dist, std::size_t i) override {
    if (dist < worst) {
      worst = dist;
      index = i;
    }
  }
  double worstDist() const override { return worst; }
  double worst;
  std::size_t index = std::size_t(-1);
};

// The k nearest points closer than a bound, nearest first; a point as far as one already kept
// goes after it (as FLANN's own k-nearest result set does).
struct BoundedKNearest : flann::ResultSet<double> {
  BoundedKNearest(int k, double bound_squared, double* dist, std::size_t* index)
      : k(k), bound(bound_squared), dist(dist), index(index) {}
  bool full() const override { return count == k; }
  void addPoint(double d, std::size_t i) override {
    if (d >= worstDist()) return;
    int at = count < k ? count++ : k - 1;
    for (; at > 0 && dist[at - 1] > d; --at) {
      dist[at] = dist[at - 1];
      index[at] = index[at - 1];
    }
    dist[at] = d;
    index[at] = i;
  }
  double worstDist() const override { return count == k ? dist[k - 1] : bound; }
  int k;
  double bound;
  double* dist;
  std::size_t* index;
  int count = 0;
};

}  // namespace

template <int D>
NearestPointIndex<D>::NearestPointIndex(Points<D> points) : impl_(std::make_unique<Impl>()) {
  if (!points.empty()) require_valid_points(points, "data points");
  impl_->points = std::move(points);
  if (impl_->points.empty()) return;
  const auto& p = impl_->points;
  impl_->flat.resize(p.size() * D);
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int d = 0; d < D; ++d) impl_->flat[i * D + d] = p[i][d];
  }
  flann::Matrix<double> data(impl_->flat.data(), p.size(), D);
  impl_->index = std::make_unique<flann::KDTreeSingleIndex<flann::L2<double>>>(
      data, flann::KDTreeSingleIndexParams(/*leaf_max_size=*/12));
  impl_->index->buildIndex();
}

template <int D>
NearestPointIndex<D>::~NearestPointIndex() = default;
template <int D>
NearestPointIndex<D>::NearestPointIndex(NearestPointIndex&&) noexcept = default;
template <int D>
NearestPointIndex<D>& NearestPointIndex<D>::operator=(NearestPointIndex&&) noexcept = default;

template <int D>
const Points<D>& NearestPointIndex<D>::points() const {
  return impl_->points;
}

template <int D>
void NearestPointIndex<D>::query(const Points<D>& queries, std::vector<double>& distance,
                                 std::vector<Index>* nearest, int threads) const {
  std::vector<Index> found;
  query_within(queries, std::vector<double>(queries.size(), std::numeric_limits<double>::infinity()), distance,
               found, threads);
  if (nearest) *nearest = std::move(found);
}

template <int D>
void NearestPointIndex<D>::query_within(const Points<D>& queries, const std::vector<double>& bound,
                                        std::vector<double>& distance, std::vector<Index>& nearest,
                                        int threads) const {
  const long n = long(queries.size());
  distance.assign(queries.size(), std::numeric_limits<double>::infinity());
  nearest.assign(queries.size(), -1);
  if (!impl_->index) return;
  const flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, 0.0f, false);
  const Points<D>& p = impl_->points;
#pragma omp parallel num_threads(detail::thread_count(threads))
  {
    Index hint = -1;  // the nearest point of this thread's previous query
#pragma omp for schedule(static)
    for (long i = 0; i < n; ++i) {
      const Vec<D>& q = queries[std::size_t(i)];
      double bound2 = bound[std::size_t(i)] * bound[std::size_t(i)];
      // Any point at most the hint's distance away is found: the bound only prunes.
      if (hint >= 0) bound2 = std::min(bound2, (q - p[std::size_t(hint)]).squaredNorm() * (1.0 + 1e-9) + 1e-300);
      BoundedNearest found(bound2);
      impl_->index->findNeighbors(found, q.data(), params);
      if (found.index == std::size_t(-1)) continue;
      if (std::sqrt(found.worst) >= bound[std::size_t(i)]) continue;
      distance[std::size_t(i)] = std::sqrt(found.worst);
      nearest[std::size_t(i)] = hint = Index(found.index);
    }
  }
}

template <int D>
void NearestPointIndex<D>::query_k(const Points<D>& queries, int k, LargeVector<Index>& nearest,
                                   int threads) const {
  const long n = long(queries.size());
  const int kk = std::max(1, std::min<int>(k, int(impl_->points.size())));
  nearest.assign(queries.size() * std::size_t(k), -1);
  if (!impl_->index) return;
  const flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, 0.0f, true);
  // In Z-order, each query's k nearest lie within the previous one's k-th distance plus the
  // step between them: a tight bound from the start of the search.
  const std::vector<Index> order = z_order<D>(queries);
#pragma omp parallel num_threads(detail::thread_count(threads))
  {
    std::vector<double> dist(std::size_t(kk), 0.0);
    std::vector<std::size_t> index(std::size_t(kk), 0);
    const Vec<D>* previous = nullptr;
    double previous_reach = 0.0;
#pragma omp for schedule(static)
    for (long r = 0; r < n; ++r) {
      const std::size_t i = std::size_t(order[std::size_t(r)]);
      const Vec<D>& q = queries[i];
      const double bound = previous ? previous_reach + (q - *previous).norm() : std::numeric_limits<double>::infinity();
      BoundedKNearest found(kk, bound * bound * (1.0 + 1e-9) + 1e-300, dist.data(), index.data());
      impl_->index->findNeighbors(found, q.data(), params);
      if (found.count < kk) {  // only if round-off defeated the margin
        found = BoundedKNearest(kk, std::numeric_limits<double>::infinity(), dist.data(), index.data());
        impl_->index->findNeighbors(found, q.data(), params);
      }
      for (int j = 0; j < k; ++j) nearest[i * std::size_t(k) + std::size_t(j)] = Index(index[std::size_t(std::min(j, kk - 1))]);
      previous = &q;
      previous_reach = std::sqrt(dist[std::size_t(kk) - 1]);
    }
  }
}

template <int D>
void NearestPointIndex<D>::within(const Vec<D>& q, double radius, std::vector<Index>& found) const {
  found.clear();
  if (!impl_->index) return;
  double coords[D];
  for (int d = 0; d < D; ++d) coords[d] = q[d];
  flann::Matrix<double> query(coords, 1, D);
  std::vector<std::vector<std::size_t>> indices;
  std::vector<std::vector<double>> dist2;
  flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED, 0.0f, /*sorted=*/false);
  impl_->index->radiusSearch(query, indices, dist2, float(radius * radius * (1 + 1e-6)), params);
  found.assign(indices[0].begin(), indices[0].end());
}

template <int D>
double NearestPointIndex<D>::distance(const Vec<D>& q) const {
  double d = std::numeric_limits<double>::infinity();
  nearest(q, d);
  return d;
}

template <int D>
Index NearestPointIndex<D>::nearest(const Vec<D>& q, double& distance) const {
  BoundedNearest found(std::numeric_limits<double>::infinity());
  if (impl_->index) impl_->index->findNeighbors(found, q.data(), flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED, 0.0f, false));
  distance = found.index == std::size_t(-1) ? std::numeric_limits<double>::infinity() : std::sqrt(found.worst);
  return found.index == std::size_t(-1) ? Index(-1) : Index(found.index);
}

template class NearestPointIndex<2>;
template class NearestPointIndex<3>;

}  // namespace lsr
