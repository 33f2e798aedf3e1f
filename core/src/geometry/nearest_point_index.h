// SPDX-License-Identifier: BSD-3-Clause
/// @file nearest_point_index.h
/// @brief Exact nearest-neighbour queries to a point set (a FLANN kd-tree): the unsigned
/// distance d(x) to the data of eq. (1).
#pragma once

#include "lsrecon/core/large_array_allocator.h"
#include "lsrecon/core/types.h"

#include <memory>
#include <vector>

namespace lsr {

/// @brief A kd-tree over a fixed point set. Queries are exact (no approximate search), batched
/// and run on several threads; results do not depend on the thread count.
template <int D>
class NearestPointIndex {
 public:
  /// @brief Empty, the index finds nothing (a worker's empty run of the cloud).
  /// @throw InvalidInput if points holds a non-finite coordinate.
  explicit NearestPointIndex(Points<D> points);
  ~NearestPointIndex();
  NearestPointIndex(NearestPointIndex&&) noexcept;
  NearestPointIndex& operator=(NearestPointIndex&&) noexcept;

  const Points<D>& points() const;

  /// @brief For each query, the distance to its nearest data point and, if nearest is given,
  /// that point's index (the lowest-index one among exact ties is not guaranteed).
  /// @param threads number of threads, 0 for all cores.
  void query(const Points<D>& queries, std::vector<double>& distance,
             std::vector<Index>* nearest = nullptr, int threads = 0) const;

  /// @brief For each query, its nearest data point if that lies closer than bound[i]
  /// (otherwise distance +inf and index -1): exact, as query() where found, and cheaper the
  /// tighter the bounds. Each search is also bounded by the distance to the previous query's
  /// nearest point on the same thread: consecutive queries near each other are cheapest.
  void query_within(const Points<D>& queries, const std::vector<double>& bound, std::vector<double>& distance,
                    std::vector<Index>& nearest, int threads = 0) const;
  /// @brief The k nearest data points of each query (k * #queries indices, nearest first;
  /// fewer than k points in the set repeat the last found index).
  void query_k(const Points<D>& queries, int k, LargeVector<Index>& nearest, int threads = 0) const;

  /// @brief Indices of the data points within radius of q (any order).
  void within(const Vec<D>& q, double radius, std::vector<Index>& found) const;

  /// @brief Distance from one point to the data.
  double distance(const Vec<D>& q) const;

  /// @brief The data point nearest to q (-1 for an empty set) and its distance, on the calling
  /// thread.
  Index nearest(const Vec<D>& q, double& distance) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lsr
