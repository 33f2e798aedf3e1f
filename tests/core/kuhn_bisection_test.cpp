// SPDX-License-Identifier: BSD-3-Clause
/// @file kuhn_bisection_test.cpp
/// @brief Conformity and shape regularity of bisection refinement, under arbitrary
/// (random) refinement orders, in 2D and 3D.
#include "core/mesh_checks.h"
#include "mesh/adaptive_refinement.h"
#include "mesh/kuhn_bisection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace lsr {
namespace {

// Maubach bisection of a Kuhn simplex cycles through D similarity classes. In 2D all are
// isosceles right triangles: D!|K|/L^D = 2 * (1/2) / 2 = 1/2. In 3D the classes have
// (|K|, L_max) = (1/6, sqrt 3), (1/12, sqrt 2), (1/24, 1) in a unit cube, so the quality
// 6|K|/L^3 takes the values 0.192, 0.177, 0.25: the minimum is 1/(4 sqrt 2).
template <int D>
double quality_lower_bound() {
  return D == 2 ? 0.5 : 1.0 / (4.0 * std::sqrt(2.0));
}

template <int D>
void refine_randomly(KuhnBisectionForest<D>& forest, int bisections, unsigned seed) {
  std::mt19937 rng(seed);
  for (int i = 0; i < bisections; ++i) {
    std::uniform_int_distribution<Index> pick(0, Index(forest.simplices().size()) - 1);
    Index s = pick(rng);
    while (!forest.is_leaf(s)) s = forest.simplices()[s].first_child + Index(rng() % 2);
    forest.refine(s);
  }
}

template <int D>
void check_random_refinement(int cells, int bisections) {
  KuhnBisectionForest<D> forest(cells);
  refine_randomly(forest, bisections, 42);
  const AdaptiveMesh<D> adaptive = leaf_mesh(std::move(forest));
  const auto& mesh = adaptive.mesh;
  ASSERT_GT(mesh.simplices.size(), std::size_t(bisections));
  EXPECT_EQ(testing::conformity_error(mesh), "");
  double volume = 0.0;
  double worst = 1.0;
  for (Index s = 0; s < Index(mesh.simplices.size()); ++s) {
    ASSERT_GT(signed_measure(mesh, s), 0.0) << "simplex " << s;
    volume += signed_measure(mesh, s);
    worst = std::min(worst, testing::shape_quality(mesh, s));
  }
  EXPECT_NEAR(volume, 1.0, 1e-12);
  EXPECT_GE(worst, quality_lower_bound<D>() - 1e-12);
}

TEST(KuhnBisection, BackgroundMeshIsConformingAndTilesTheBox) {
  check_random_refinement<2>(3, 0);
  check_random_refinement<3>(3, 0);
}

TEST(KuhnBisection, RandomRefinementStaysConformingIn2D) { check_random_refinement<2>(2, 3000); }

TEST(KuhnBisection, RandomRefinementStaysConformingIn3D) { check_random_refinement<3>(2, 3000); }

TEST(KuhnBisection, DeepLocalRefinementStaysConforming) {
  // Always refining the leaf holding one corner forces long closure chains.
  KuhnBisectionForest<3> forest(1);
  for (int i = 0; i < 40; ++i) {
    Index s = 0;
    while (!forest.is_leaf(s)) s = forest.simplices()[s].first_child;
    forest.refine(s);
  }
  const AdaptiveMesh<3> adaptive = leaf_mesh(std::move(forest));
  EXPECT_EQ(testing::conformity_error(adaptive.mesh), "");
}

TEST(KuhnBisection, SizeIsTheKuhnCubeSide) {
  KuhnBisectionForest<3> forest(4);
  EXPECT_NEAR(forest.size(0), 0.25, 1e-15);
  // D bisections give the Kuhn simplices of cubes of half the side.
  Index s = 0;
  for (int i = 0; i < 3; ++i) {
    forest.refine(s);
    s = forest.simplices()[s].first_child;
  }
  EXPECT_NEAR(forest.size(s), 0.125, 1e-15);
}

// size() reads a size per level: every simplex of a level must have it. On power-of-two grids
// (the adaptive mesh's) every coordinate is dyadic and the sizes are equal to the bit; on others
// the coordinates (k/3) carry rounding errors of 2^-54 each, so edges differ by a few 2^-53.
template <int D>
void check_sizes_per_level(int cells, double tolerance) {
  KuhnBisectionForest<D> forest(cells);
  refine_randomly(forest, 3000, 7);
  for (Index s = 0; s < Index(forest.simplices().size()); ++s) {
    const auto& v = forest.simplices()[s].v;
    double longest2 = 0.0;
    for (int i = 0; i <= D; ++i) {
      for (int j = i + 1; j <= D; ++j) longest2 = std::max(longest2, (forest.vertices()[v[i]] - forest.vertices()[v[j]]).squaredNorm());
    }
    const double measured = std::sqrt(longest2 / D);
    if (tolerance == 0.0) {
      ASSERT_EQ(forest.size(s), measured) << "simplex " << s;
    } else {
      ASSERT_NEAR(forest.size(s), measured, tolerance) << "simplex " << s;
    }
  }
}

TEST(KuhnBisection, EverySimplexHasItsLevelsSize) {
  check_sizes_per_level<2>(4, 0.0);
  check_sizes_per_level<3>(4, 0.0);
  check_sizes_per_level<2>(3, 8 * std::ldexp(1.0, -53));
  check_sizes_per_level<3>(3, 8 * std::ldexp(1.0, -53));
}

TEST(KuhnBisection, RejectsAbsurdGrids) {
  EXPECT_THROW(KuhnBisectionForest<3>(0), InvalidInput);
  EXPECT_THROW(KuhnBisectionForest<3>(5000), InvalidInput);
}

}  // namespace
}  // namespace lsr
