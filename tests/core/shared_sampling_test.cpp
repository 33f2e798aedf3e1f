// SPDX-License-Identifier: BSD-3-Clause
/// @file shared_sampling_test.cpp
/// @brief The sampling shared among workers, each holding a share of the input (threads here,
/// MPI ranks in lsrecon-mpi): worker 0 ends with what one process computes, to the bit; the
/// exact median of values spread over the workers.
#include "lsrecon/testdata/shape_corpus.h"
#include "sampling/sampled_data.h"
#include "sampling/worker_collectives.h"
#include "thread_exchange.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <thread>

namespace lsr {
namespace {

using detail::SampledData;

template <class T, class A>
bool same_bytes(const std::vector<T, A>& a, const std::vector<T, A>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(static_cast<const void*>(a.data()), static_cast<const void*>(b.data()), a.size() * sizeof(T)) == 0);
}

// Runs f(worker, exchange) on `workers` threads.
template <class F>
void on_workers(int workers, F f) {
  ThreadExchange::Meeting meeting(workers);
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w) {
    threads.emplace_back([&, w] {
      const ThreadExchange exchange(w, meeting);
      f(w, exchange);
    });
  }
  for (auto& t : threads) t.join();
}

TEST(WorkerCollectives, TheMedianOverWorkersIsTheMedianOfAllValues) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const std::size_t n : {1, 2, 7, 1000, 1001}) {
    std::vector<double> all(n);
    for (double& v : all) v = std::round(normal(rng) * 20.0) / 8.0;  // negatives, repeats, zeros
    // Worker 1 holds nothing; 0 and 2 uneven shares.
    const std::size_t cut = n / 3;
    std::vector<double> got(3);
    on_workers(3, [&](int w, const TileExchange& x) {
      const double* first = all.data() + (w == 0 ? 0 : cut);
      const std::size_t count = w == 0 ? cut : w == 1 ? 0 : n - cut;
      got[std::size_t(w)] = median_over_workers(&x, first, count);
    });
    for (const double g : got) EXPECT_EQ(g, median(all)) << n;
  }
}

// Worker 0's sample equals one process's, every byte: the box, the medians, the sample's points,
// their estimates and scales, the points each stands for, and the counts. Worker w passes the
// input's points [cut[w], cut[w + 1]).
void expect_workers_match(const Points<3>& cloud, const std::vector<std::size_t>& cut, const ReconstructionOptions& o) {
  ReconstructionResult<3> one_r;
  detail::StageClock one_clock(one_r.seconds, one_r.stages);
  const SampledData<3> one = detail::sampled_data<3>(cloud, o, HeightFieldsAt::all_and_rims, Progress(), one_r, one_clock);
  const int workers = int(cut.size()) - 1;
  std::vector<std::optional<SampledData<3>>> each(cut.size() - 1);
  std::vector<ReconstructionResult<3>> r(cut.size() - 1);
  on_workers(workers, [&](int w, const TileExchange& x) {
    ReconstructionOptions ow = o;
    ow.limits.exchange = std::shared_ptr<const TileExchange>(&x, [](const TileExchange*) {});
    ow.limits.threads = 1;
    const std::size_t at = std::size_t(w);
    detail::StageClock clock(r[at].seconds, r[at].stages);
    each[at] = detail::shared_sampled_data<3>(Points<3>(cloud.begin() + long(cut[at]), cloud.begin() + long(cut[at + 1])), ow,
                                              HeightFieldsAt::all_and_rims, Progress(), r[at], clock);
  });
  ASSERT_TRUE(each[0].has_value());
  for (int w = 1; w < workers; ++w) EXPECT_FALSE(each[std::size_t(w)].has_value());
  const SampledData<3>& two = *each[0];
  EXPECT_EQ(one.box.scale(), two.box.scale());
  EXPECT_EQ(one.box.center(), two.box.center());
  EXPECT_EQ(one.spacing, two.spacing);
  EXPECT_EQ(one.noise, two.noise);
  EXPECT_TRUE(same_bytes(one.data.points(), two.data.points()));
  EXPECT_TRUE(same_bytes(one.point_scale, two.point_scale));
  EXPECT_EQ(one.left_out.represented, two.left_out.represented);
  EXPECT_TRUE(same_bytes(one.sampling.spacing, two.sampling.spacing));
  EXPECT_TRUE(same_bytes(one.sampling.noise, two.sampling.noise));
  EXPECT_TRUE(same_bytes(one.sampling.normals, two.sampling.normals));
  EXPECT_TRUE(same_bytes(one.sampling.gap, two.sampling.gap));
  EXPECT_TRUE(same_bytes(one.sampling.rim, two.sampling.rim));
  EXPECT_TRUE(same_bytes(one.sampling.height_fields, two.sampling.height_fields));
  EXPECT_EQ(one.sampling.scan_lines, two.sampling.scan_lines);
  for (const ReconstructionResult<3>& rw : r) {
    EXPECT_EQ(rw.input_points, cloud.size());
    EXPECT_EQ(rw.skipped_points, one_r.skipped_points);
    EXPECT_EQ(rw.duplicate_points, one_r.duplicate_points);
    EXPECT_EQ(rw.outlier_points, one_r.outlier_points);
  }
}

// Scan lines with a hole and a wave, a little noise: rims and height fields.
Points<3> scan_lines() {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  Points<3> cloud;
  const double a = 0.001;
  for (int j = 0; j < 30; ++j) {
    for (int i = 0; i < 300; ++i) {
      const Vec<3> x(0.3 + a * i, 0.3 + 10 * a * j, 0.5 + 3e-3 * std::sin(20.0 * a * i) + 2e-4 * noise(rng));
      if ((x.head<2>() - Vec<3>(0.45, 0.45, 0).head<2>()).norm() > 0.05) cloud.push_back(x);
    }
  }
  return cloud;
}

// Every path: rims, isolated points (dropped, then the box and every estimate again), copies
// whose first copy another worker holds, NaN points, a worker without input points, and a mesh
// coarser than the data (the sample thinned).
TEST(SharedSampling, WorkersGiveWorkerZeroWhatOneProcessComputes) {
  Points<3> cloud = scan_lines();
  for (int k = 0; k < 5; ++k) cloud.emplace_back(0.2 + 0.1 * k, 0.9, 0.1 + 0.05 * k);  // isolated
  cloud.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0.5, 0.5);
  for (std::size_t i = 0; i < 200; i += 2) cloud.push_back(cloud[i]);  // copies, at the end
  ReconstructionOptions o;
  o.mesh.max_resolution = 32;
  ReconstructionResult<3> r;
  detail::StageClock clock(r.seconds, r.stages);
  const SampledData<3> one = detail::sampled_data<3>(cloud, o, HeightFieldsAt::all_and_rims, Progress(), r, clock);
  ASSERT_GT(r.outlier_points, 0u);
  ASSERT_GT(r.duplicate_points, 0u);
  ASSERT_NE(std::count(one.sampling.rim.begin(), one.sampling.rim.end(), 1), 0);
  ASSERT_FALSE(one.left_out.represented.empty());  // thinned
  expect_workers_match(cloud, {0, cloud.size() / 2, cloud.size() / 2, cloud.size()}, o);
}

// A flood of copies of one point: the workers' samples of the keys repeat it, cuts of the curve
// fall on it, and a worker's run is empty or that one point (no point of it in the sample).
TEST(SharedSampling, AWorkerWithAnEmptyRunTakesPart) {
  Points<3> cloud = scan_lines();
  cloud.insert(cloud.end(), 3 * cloud.size(), cloud[1000]);
  ReconstructionOptions o;
  o.mesh.max_resolution = 32;
  expect_workers_match(cloud, {0, cloud.size() / 4, cloud.size() / 2, 3 * cloud.size() / 4, cloud.size()}, o);
}

}  // namespace
}  // namespace lsr
