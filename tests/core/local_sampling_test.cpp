// SPDX-License-Identifier: BSD-3-Clause
/// @file local_sampling_test.cpp
/// @brief The spacing rule on regular and random samples, the noise and normal estimates; tiles
/// and workers give every point the same estimate.
#include "lsrecon/testdata/shape_corpus.h"
#include "sampling/cloud_halo.h"
#include "sampling/local_sampling.h"
#include "thread_exchange.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <thread>
#include <type_traits>

namespace lsr {
namespace {

const double kPi = std::acos(-1.0);

TEST(LocalSampling, RegularSamplesGiveTheirGap) {
  // Hexagonal lattice in the plane z = 0.5 (six neighbours at distance a), and an evenly
  // spaced circle (two neighbours at the chord): the rule's k is their neighbour count.
  const double a = 0.01;
  Points<3> lattice;
  for (int i = 0; i < 60; ++i) {
    for (int j = 0; j < 60; ++j) lattice.emplace_back(0.2 + a * (i + 0.5 * (j % 2)), 0.2 + a * std::sqrt(0.75) * j, 0.5);
  }
  const LocalSampling<3> s = estimate_local_sampling(NearestPointIndex<3>(lattice));
  EXPECT_NEAR(median(s.spacing), a, 1e-9);
  EXPECT_NEAR(std::abs(s.normals[1830].z()), 1.0, 1e-9);
  EXPECT_LT(median(s.noise), 1e-9);

  const int n = 1000;
  Points<2> circle;
  for (int i = 0; i < n; ++i) circle.emplace_back(0.5 + 0.3 * std::cos(2 * kPi * i / n), 0.5 + 0.3 * std::sin(2 * kPi * i / n));
  const LocalSampling<2> c = estimate_local_sampling(NearestPointIndex<2>(circle));
  EXPECT_NEAR(median(c.spacing), 2 * 0.3 * std::sin(kPi / n), 1e-9);
}

// Scan lines of a plane: samples a apart along x, lines 10 a apart in y. The 16 nearest of a
// point lie on its line (their PCA normal is any direction across it, their spacing 3 a, the
// line's); the 32 nearest reach the next lines. Read as scan lines, the normal is the plane's and
// the spacing at least the largest empty disc between two lines (radius 5 a, seen from
// candidate centres at 0.96 of it) over kHoleToSpacing.
TEST(LocalSampling, ScanLinesGiveThePlanesNormalAndASpacingThatSeesTheGapBetweenLines) {
  const double a = 0.002, gap = 10 * a;
  Points<3> lines;
  for (int j = 0; j < 20; ++j) {
    for (int i = 0; i < 200; ++i) lines.emplace_back(0.3 + a * i, 0.3 + gap * j, 0.5);
  }
  const LocalSampling<3> s = estimate_local_sampling(NearestPointIndex<3>(lines));
  const std::size_t middle = 10 * 200 + 100;
  EXPECT_NEAR(std::abs(s.normals[middle].z()), 1.0, 1e-9);
  EXPECT_GE(s.spacing[middle], 0.96 * 0.5 * gap / LocalSampling<3>::kHoleToSpacing);
  EXPECT_LE(s.spacing[middle], 0.5 * gap / LocalSampling<3>::kHoleToSpacing + 1e-12);
  EXPECT_LT(median(s.noise), 1e-9);
}

// The same lines read as the caller says: as scattered samples, a line point's spacing is the
// 6th distinct neighbour's distance along its line, 3 a; random samples read as scan lines take
// spacings at least their own (the empty disc only raises them).
TEST(LocalSampling, ScanLinesCanBeSetEitherWay) {
  const double a = 0.002, gap = 10 * a;
  Points<3> lines;
  for (int j = 0; j < 20; ++j) {
    for (int i = 0; i < 200; ++i) lines.emplace_back(0.3 + a * i, 0.3 + gap * j, 0.5);
  }
  const NearestPointIndex<3> line_index(lines);
  const std::size_t middle = 10 * 200 + 100;
  EXPECT_TRUE(estimate_local_sampling(line_index).scan_lines);
  EXPECT_TRUE(estimate_local_sampling(line_index, 0, HeightFieldsAt::none, Progress(), {}, ScanLines::yes).scan_lines);
  const LocalSampling<3> scattered = estimate_local_sampling(line_index, 0, HeightFieldsAt::none, Progress(), {}, ScanLines::no);
  EXPECT_FALSE(scattered.scan_lines);
  EXPECT_NEAR(scattered.spacing[middle], 3 * a, 1e-12);

  const Points<3> random = sample_implicit_surface([](const Vec<3>& x) { return x.norm() - 1.0; }, -1.1 * Vec<3>::Ones(),
                                                   1.1 * Vec<3>::Ones(), 5000, 5);
  const NearestPointIndex<3> random_index(random);
  const LocalSampling<3> automatic = estimate_local_sampling(random_index);
  EXPECT_FALSE(automatic.scan_lines);
  const LocalSampling<3> as_lines = estimate_local_sampling(random_index, 0, HeightFieldsAt::none, Progress(), {}, ScanLines::yes);
  EXPECT_TRUE(as_lines.scan_lines);
  for (std::size_t i = 0; i < random.size(); ++i) ASSERT_GE(as_lines.spacing[i], automatic.spacing[i]);
}

// Dense noisy scan lines: the same plane with noise sigma = 6 a along z. The 16 nearest are
// mostly a noisy piece of one line, spread along x and z, not along y: their median elongation
// (about 0.56) reads like i.i.d. samples, and the PCA normal of most lies along y, across the
// line (61% of these points; measured with numpy on the same construction). The 32 nearest
// reach the next lines and see the plane (99% along z): read as scan lines by the disagreement
// of the two, the points take those normals.
TEST(LocalSampling, ScanLinesHiddenByTheirNoiseAreStillReadAsScanLines) {
  const double a = 0.001, gap = 10 * a, sigma = 6 * a;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, sigma);
  Points<3> lines;
  for (int j = 0; j < 20; ++j) {
    for (int i = 0; i < 300; ++i) lines.emplace_back(0.3 + a * i, 0.3 + gap * j, 0.5 + noise(rng));
  }
  const LocalSampling<3> s = estimate_local_sampling(NearestPointIndex<3>(lines));
  int along_z = 0, inner = 0;
  for (int j = 2; j < 18; ++j) {
    for (int i = 30; i < 270; ++i, ++inner) along_z += std::abs(s.normals[std::size_t(j * 300 + i)].z()) > std::sqrt(0.5);
  }
  EXPECT_GT(along_z, 0.9 * inner);
}

TEST(LocalSampling, RandomSurfaceSamplesGiveTheSixthNeighbourScaleAndIgnoreDuplicates) {
  // i.i.d. points of density rho on a surface: the 6th-neighbour distance r has
  // pi rho r^2 ~ Gamma(6, 1), whose median is 5.67; so median(spacing) ~ sqrt(5.67 / (pi rho)).
  const int n = 20000;
  Points<3> p = sample_implicit_surface([](const Vec<3>& x) { return x.norm() - 1.0; }, -1.1 * Vec<3>::Ones(),
                                        1.1 * Vec<3>::Ones(), n, 5);
  const double rho = n / (4 * kPi);
  const double expected = std::sqrt(5.67 / (kPi * rho));
  const LocalSampling<3> s = estimate_local_sampling(NearestPointIndex<3>(p));
  // The median filter and the curvature (r / R ~ 0.05) move it by a few percent.
  EXPECT_NEAR(median(s.spacing), expected, 0.08 * expected);
  // Every point twice: the same scales.
  Points<3> twice = p;
  twice.insert(twice.end(), p.begin(), p.end());
  const LocalSampling<3> t = estimate_local_sampling(NearestPointIndex<3>(twice));
  EXPECT_NEAR(median(t.spacing), median(s.spacing), 0.08 * expected);
  for (std::size_t i = 0; i < 100; ++i) EXPECT_GT(std::abs(s.normals[i].dot(p[i])), 0.95);
}

TEST(LocalSampling, NoiseOfAPlaneIsItsDeviation) {
  // A plane with Gaussian noise sigma across it: the smallest PCA deviation of 16 neighbours is
  // sigma times sqrt((k - 1) / k) on average; the median filter keeps it within 20%.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double sigma = 0.002;
  Points<3> p;
  for (int i = 0; i < 20000; ++i) p.emplace_back(unit(rng), unit(rng), 0.5 + sigma * gauss(rng));
  const LocalSampling<3> s = estimate_local_sampling(NearestPointIndex<3>(p));
  EXPECT_NEAR(median(s.noise), sigma, 0.2 * sigma);
}

TEST(LocalSampling, CurvatureOfRandomSphereSamplesConvergesLikeTheSquaredNeighbourhood) {
  // A quadric fitted to h = x^2 / (2R) + |x|^4 / (8R^3) + ... over neighbours within r misses
  // the quartic term: curvature error ~ r^2 / R^3, with pi rho r^2 = 16 (the neighbourhood).
  const TestShape sphere = make_test_shape("sphere");  // R = 1
  double previous = 0.0;
  for (const int n : {2000, 20000}) {
    const LocalSampling<3> s = estimate_local_sampling(NearestPointIndex<3>(sample_test_shape(sphere, n).points), 0, HeightFieldsAt::all);
    std::vector<double> error;
    for (const HeightField<3>& f : s.height_fields) error.push_back(std::abs(f.largest_curvature() - 1.0));
    const double r2 = 16.0 / (kPi * n / (4 * kPi));
    EXPECT_LT(median(error), r2) << n;
    if (previous > 0.0) {
      EXPECT_LT(median(error), 0.5 * previous);  // n x10: r^2 / 10
    }
    previous = median(error);
  }
}

template <class T, class A>
bool same_bytes(const std::vector<T, A>& a, const std::vector<T, A>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expect_same(const LocalSampling<3>& a, const LocalSampling<3>& b, const std::string& what) {
  EXPECT_TRUE(same_bytes(a.spacing, b.spacing)) << what;
  EXPECT_TRUE(same_bytes(a.noise, b.noise)) << what;
  EXPECT_TRUE(same_bytes(a.normals, b.normals)) << what;
  EXPECT_TRUE(same_bytes(a.gap, b.gap)) << what;
  EXPECT_TRUE(same_bytes(a.rim, b.rim)) << what;
  EXPECT_TRUE(same_bytes(a.height_fields, b.height_fields)) << what;
}

// drop_isolated's points (the nearest distinct neighbour beyond 3 spacings), found before the
// spacing is raised over gaps, are those the whole estimate gives. Scan lines of a plane (a
// apart along x, lines 10 a apart): a point 0.1 above it is isolated; one 15 a above a line is
// beyond 3 of its neighbours' spacing along their line (3 a) but within 3 of the spacing raised
// to the gap between lines (about 9 a), so it is kept. A random curve with a point far off.
TEST(LocalSampling, IsolatedPointsFoundEarlyAreThoseOfTheWholeEstimate) {
  const double a = 0.002, gap = 10 * a, factor = 3.0;
  Points<3> lines;
  for (int j = 0; j < 20; ++j) {
    for (int i = 0; i < 200; ++i) lines.emplace_back(0.3 + a * i, 0.3 + gap * j, 0.5);
  }
  const std::size_t far = lines.size(), hovering = far + 1;
  lines.emplace_back(0.5, 0.4, 0.6);
  lines.emplace_back(0.3 + a * 100, 0.3 + gap * 10, 0.5 + 15 * a);
  const NearestPointIndex<3> data(lines);
  const auto isolated = [&](const auto& s) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < s.gap.size(); ++i) {
      if (s.gap[i] > factor * s.spacing[i]) out.push_back(i);
    }
    return out;
  };
  const LocalSampling<3> scattered = estimate_local_sampling(data, 1, HeightFieldsAt::none, Progress(), {}, ScanLines::no);
  ASSERT_GT(scattered.gap[hovering], factor * scattered.spacing[hovering]);  // a candidate
  const LocalSampling<3> whole = estimate_local_sampling(data, 1);
  ASSERT_TRUE(whole.scan_lines);
  EXPECT_EQ(isolated(whole), std::vector<std::size_t>{far});
  for (const int tiles : {1, 7}) {
    const LocalSampling<3> early =
        estimate_local_sampling(data, 1, HeightFieldsAt::rims, Progress(), {tiles, nullptr}, ScanLines::automatic, factor);
    EXPECT_TRUE(early.stopped_at_isolated) << tiles;
    EXPECT_EQ(isolated(early), std::vector<std::size_t>{far}) << tiles;
  }
  // Without the far point nothing is isolated: the estimate runs on, to the same bytes.
  Points<3> kept = lines;
  kept.erase(kept.begin() + long(far));
  const NearestPointIndex<3> kept_data(kept);
  const LocalSampling<3> on = estimate_local_sampling(kept_data, 1, HeightFieldsAt::rims, Progress(), {}, ScanLines::automatic, factor);
  EXPECT_FALSE(on.stopped_at_isolated);
  expect_same(on, estimate_local_sampling(kept_data, 1, HeightFieldsAt::rims), "scan lines, none isolated");

  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(0.0, 2 * kPi);
  Points<2> curve;
  for (int i = 0; i < 2000; ++i) {
    const double t = angle(rng);
    curve.emplace_back(0.5 + 0.3 * std::cos(t), 0.5 + 0.3 * std::sin(t));
  }
  curve.emplace_back(0.5, 0.5);
  const NearestPointIndex<2> curve_data(curve);
  const LocalSampling<2> early = estimate_local_sampling(curve_data, 1, HeightFieldsAt::none, Progress(), {}, ScanLines::automatic, factor);
  EXPECT_TRUE(early.stopped_at_isolated);
  EXPECT_EQ(isolated(early), isolated(estimate_local_sampling(curve_data, 1)));
  EXPECT_EQ(isolated(early), std::vector<std::size_t>{curve.size() - 1});
}

// Every point's estimate is computed from its own neighbours, in the whole index or in a
// worker's run and halo, whichever tile or worker computes it; the cloud-wide decisions (scan
// lines or not, the rims' smoothness) are taken on every worker's values. So tiles and workers
// change no bit (workers: unless neighbours are exactly equidistant). The clouds
// take every path: noisy and clean scan lines (read as such by disagreement and by elongation),
// with a hole cut out and open borders (rims, height fields at them), and i.i.d. samples.
TEST(LocalSampling, TilesAndWorkersGiveEveryPointTheSameEstimate) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<std::pair<std::string, Points<3>>> clouds(3);
  for (const double sigma : {6e-3, 0.0}) {
    Points<3>& lines = clouds[sigma > 0.0 ? 0 : 1].second;
    clouds[sigma > 0.0 ? 0 : 1].first = sigma > 0.0 ? "noisy scan lines" : "scan lines";
    const double a = 0.001;
    for (int j = 0; j < 30; ++j) {
      for (int i = 0; i < 300; ++i) {
        const Vec<3> x(0.3 + a * i, 0.3 + 10 * a * j, 0.5 + sigma * a * 1e3 * noise(rng));
        if ((x.head<2>() - Vec<3>(0.45, 0.45, 0).head<2>()).norm() > 0.05) lines.push_back(x);
      }
    }
  }
  // A torus opened where x is within a tenth of the diameter of its largest.
  double largest = -1e300, smallest = 1e300;
  const Points<3> torus = sample_test_shape(make_test_shape("torus"), 6000).points;
  for (const Vec<3>& x : torus) largest = std::max(largest, x.x()), smallest = std::min(smallest, x.x());
  clouds[2].first = "random, open";
  for (const Vec<3>& x : torus) {
    if (x.x() < largest - 0.1 * (largest - smallest)) clouds[2].second.push_back(x);
  }
  for (const auto& [what, cloud] : clouds) {
    const NearestPointIndex<3> data(cloud);
    const LocalSampling<3> one = estimate_local_sampling(data, 2, HeightFieldsAt::all_and_rims);
    ASSERT_NE(std::count(one.rim.begin(), one.rim.end(), 1), 0) << what;  // the rims' path is taken
    expect_same(one, estimate_local_sampling(data, 2, HeightFieldsAt::all_and_rims, Progress(), {7, nullptr}), what + ", 7 tiles");
    // Three workers, each with a run of the cloud and its halo (cloud_halo.h). Not on the exact
    // lattice: among exactly equidistant neighbours the kd-tree's walk picks the k-th, and a
    // run's tree walks otherwise than the whole cloud's (docs/how-it-works.md, Tiles and MPI).
    if (what == "scan lines") continue;
    ThreadExchange::Meeting meeting(3);
    std::vector<LocalSampling<3>> each(3);
    std::vector<std::size_t> first(4);
    for (std::size_t w = 0; w <= 3; ++w) first[w] = w * cloud.size() / 3;
    std::vector<std::thread> workers;
    for (int w = 0; w < 3; ++w) {
      workers.emplace_back([&, w] {
        const ThreadExchange exchange(w, meeting);
        const Points<3> own(cloud.begin() + long(first[std::size_t(w)]), cloud.begin() + long(first[std::size_t(w) + 1]));
        HaloCloud<3> local = with_halo<3>(own, first[std::size_t(w)], cloud.size(), &exchange, [&] {
          return own_neighbourhoods(own, LocalSampling<3>::kHoleNeighbours, 1.5, 1, Progress());
        });
        LocalSampling<3> s = estimate_local_sampling(NearestPointIndex<3>(std::move(local.points)), 1, HeightFieldsAt::all_and_rims,
                                                     Progress(), {2, &local.halo});
        // The run's values, as one process's are laid out.
        const auto run = [&](auto& v) { v = std::decay_t<decltype(v)>(v.begin() + long(local.halo.first), v.begin() + long(local.halo.end)); };
        run(s.spacing), run(s.noise), run(s.normals), run(s.gap), run(s.rim), run(s.height_fields);
        each[std::size_t(w)] = std::move(s);
      });
    }
    for (auto& t : workers) t.join();
    for (std::size_t w = 0; w < 3; ++w) {
      LocalSampling<3> mine = one;
      const auto run = [&](auto& v) { v = std::decay_t<decltype(v)>(v.begin() + long(first[w]), v.begin() + long(first[w + 1])); };
      run(mine.spacing), run(mine.noise), run(mine.normals), run(mine.gap), run(mine.rim), run(mine.height_fields);
      expect_same(mine, each[w], what + ", worker " + std::to_string(w) + " of 3");
      EXPECT_EQ(one.scan_lines, each[w].scan_lines) << what;
    }
  }
}

}  // namespace
}  // namespace lsr
