// SPDX-License-Identifier: BSD-3-Clause
/// @file nearest_point_index_test.cpp
#include "geometry/nearest_point_index.h"
#include "lsrecon/core/errors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>

namespace lsr {
namespace {

template <int D>
Points<D> random_points(int n, unsigned seed, double lo, double hi) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  Points<D> p(n);
  for (auto& x : p) {
    for (int d = 0; d < D; ++d) x[d] = u(rng);
  }
  return p;
}

template <int D>
void check_against_brute_force(int threads) {
  const Points<D> data = random_points<D>(3000, 1, 0.0, 1.0);
  const Points<D> queries = random_points<D>(500, 2, -0.2, 1.2);
  NearestPointIndex<D> index(data);
  std::vector<double> dist;
  std::vector<Index> nearest;
  index.query(queries, dist, &nearest, threads);
  for (std::size_t q = 0; q < queries.size(); ++q) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& p : data) best = std::min(best, (p - queries[q]).norm());
    EXPECT_DOUBLE_EQ(dist[q], best);
    EXPECT_DOUBLE_EQ((data[nearest[q]] - queries[q]).norm(), best);
  }
}

TEST(NearestPointIndex, MatchesBruteForce2D) { check_against_brute_force<2>(1); }
TEST(NearestPointIndex, MatchesBruteForce3D) { check_against_brute_force<3>(1); }
TEST(NearestPointIndex, MatchesBruteForceOnSeveralThreads) { check_against_brute_force<3>(2); }

// Within the bound: the nearest point, as query() finds it; beyond: none. The queries come in
// an order whose neighbours are far apart and near alike, so that the previous query's
// nearest point is sometimes a tight bound and sometimes a useless one.
template <int D>
void check_bounded_queries(int threads) {
  const Points<D> data = random_points<D>(3000, 3, 0.0, 1.0);
  const Points<D> queries = random_points<D>(2000, 4, -0.2, 1.2);
  std::vector<double> bound(queries.size());
  for (std::size_t q = 0; q < queries.size(); ++q) bound[q] = 0.05 * double(q % 7);
  NearestPointIndex<D> index(data);
  std::vector<double> all, dist;
  std::vector<Index> all_nearest, nearest;
  index.query(queries, all, &all_nearest, threads);
  index.query_within(queries, bound, dist, nearest, threads);
  int found = 0;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    if (all[q] < bound[q]) {
      ++found;
      EXPECT_EQ(nearest[q], all_nearest[q]) << q;
      EXPECT_EQ(dist[q], all[q]) << q;
    } else {
      EXPECT_EQ(nearest[q], -1) << q;
      EXPECT_EQ(dist[q], std::numeric_limits<double>::infinity()) << q;
    }
  }
  EXPECT_GT(found, 500);
  EXPECT_LT(found, 1900);
}

TEST(NearestPointIndex, BoundedQueriesFindTheNearestPointWithinTheBoundOnly) {
  check_bounded_queries<2>(1);
  check_bounded_queries<3>(2);
}

// The k nearest, nearest first, as a brute-force sort finds them (distinct distances: random
// points), the same on any thread count; k beyond the point count repeats the last one.
template <int D>
void check_k_nearest(int k) {
  const Points<D> data = random_points<D>(2000, 5, 0.0, 1.0);
  const Points<D> queries = random_points<D>(700, 6, -0.1, 1.1);
  NearestPointIndex<D> index(data);
  LargeVector<Index> one, two;
  index.query_k(queries, k, one, 1);
  index.query_k(queries, k, two, 2);
  EXPECT_TRUE(one == two);
  std::vector<Index> by_distance(data.size());
  for (std::size_t q = 0; q < queries.size(); ++q) {
    std::iota(by_distance.begin(), by_distance.end(), 0);
    std::sort(by_distance.begin(), by_distance.end(), [&](Index a, Index b) {
      return (data[a] - queries[q]).squaredNorm() < (data[b] - queries[q]).squaredNorm();
    });
    for (int j = 0; j < k; ++j) ASSERT_EQ(one[q * k + j], by_distance[j]) << q << " " << j;
  }
  NearestPointIndex<D> three(Points<D>(data.begin(), data.begin() + 3));
  three.query_k(queries, 5, one, 2);
  for (std::size_t q = 0; q < queries.size(); ++q) EXPECT_EQ(one[q * 5 + 4], one[q * 5 + 2]);
}

TEST(NearestPointIndex, KNearestMatchBruteForce) {
  check_k_nearest<2>(4);
  check_k_nearest<3>(12);
  check_k_nearest<3>(30);
}

TEST(NearestPointIndex, DuplicatesAndSinglePointsWork) {
  NearestPointIndex<3> one(Points<3>{Vec<3>(1, 2, 3)});
  EXPECT_DOUBLE_EQ(one.distance(Vec<3>(1, 2, 4)), 1.0);
  NearestPointIndex<3> dup(Points<3>(50, Vec<3>(0, 0, 0)));
  EXPECT_DOUBLE_EQ(dup.distance(Vec<3>(0, 3, 4)), 5.0);
}

// Empty: a worker's empty run of the cloud (tile_exchange.h); every query finds nothing.
TEST(NearestPointIndex, AnEmptyIndexFindsNothingAndNonFiniteInputIsRejected) {
  const NearestPointIndex<3> empty(Points<3>{});
  const Points<3> q{Vec<3>(0, 0, 0), Vec<3>(1, 1, 1)};
  std::vector<double> distance;
  std::vector<Index> nearest;
  empty.query(q, distance, &nearest, 1);
  EXPECT_EQ(nearest, std::vector<Index>(2, -1));
  EXPECT_TRUE(std::isinf(distance[0]) && std::isinf(distance[1]));
  LargeVector<Index> k;
  empty.query_k(q, 4, k, 1);
  EXPECT_TRUE(std::all_of(k.begin(), k.end(), [](Index i) { return i == -1; }));
  EXPECT_TRUE(std::isinf(empty.distance(q[0])));
  Points<3> p{Vec<3>(0, 0, 0), Vec<3>(std::nan(""), 0, 0)};
  EXPECT_THROW(NearestPointIndex<3>{p}, InvalidInput);
  p[1] = Vec<3>(std::numeric_limits<double>::infinity(), 0, 0);
  EXPECT_THROW(NearestPointIndex<3>{p}, InvalidInput);
}

}  // namespace
}  // namespace lsr
