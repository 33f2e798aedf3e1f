// SPDX-License-Identifier: BSD-3-Clause
/// @file unsupported_parts_test.cpp
/// @brief Parts of a level set that no sample is nearest to go, the others stay: analytic
/// balls and shells on a uniform Kuhn mesh, samples on some of their spheres only.
#include "lsrecon/core/level_set_extraction.h"
#include "mesh/adaptive_refinement.h"
#include "mesh/kuhn_bisection.h"
#include "start/outside_flood_fill.h"
#include "surface/unsupported_parts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>
#include <set>

namespace lsr {
namespace {

template <int D>
struct Grid {
  SimplexMesh<D> mesh = leaf_mesh(KuhnBisectionForest<D>(24)).mesh;
  std::vector<double> sample(const std::function<double(const Vec<D>&)>& f) const {
    std::vector<double> u(mesh.vertices.size());
    for (std::size_t v = 0; v < u.size(); ++v) u[v] = f(mesh.vertices[v]);
    return u;
  }
};

// Parts of one sign, those of {u >= 0} reaching a wall left out.
template <int D>
std::size_t parts(const SimplexMesh<D>& mesh, const std::vector<double>& u, bool negative) {
  std::vector<char> member(u.size());
  for (std::size_t v = 0; v < u.size(); ++v) member[v] = (u[v] < 0.0) == negative;
  const std::vector<Index> root = vertex_components(mesh, member);
  std::set<Index> roots, outside;
  for (std::size_t v = 0; v < u.size(); ++v) {
    if (root[v] < 0) continue;
    roots.insert(root[v]);
    if (on_wall<D>(mesh.vertices[v])) outside.insert(root[v]);
  }
  return roots.size() - outside.size();
}

// n random points on the sphere (circle) of centre c and radius r.
template <int D>
void add_sphere_points(Points<D>& points, const Vec<D>& c, double r, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  for (int i = 0; i < n; ++i) {
    Vec<D> d;
    for (int k = 0; k < D; ++k) d[k] = g(rng);
    points.push_back(c + r * d.normalized());
  }
}

template <int D>
double ball(const Vec<D>& x, const Vec<D>& c, double r) { return (x - c).norm() - r; }

template <int D>
std::size_t drop(const Grid<D>& grid, std::vector<double>& u, const Points<D>& points) {
  const LevelSetMesh<D> surface = extract_zero_level_set(grid.mesh, u);
  return drop_unsupported_parts(grid.mesh, surface, points, u);
}

template <int D>
void two_balls_keep_the_one_with_data() {
  const Grid<D> grid;
  const Vec<D> a = Vec<D>::Constant(0.5) - 0.2 * Vec<D>::Unit(0), b = Vec<D>::Constant(0.5) + 0.22 * Vec<D>::Unit(0);
  const auto f = [&](const Vec<D>& x) { return std::min(ball<D>(x, a, 0.15), ball<D>(x, b, 0.1)); };
  Points<D> on_a;
  add_sphere_points<D>(on_a, a, 0.15, 300, 1);
  std::vector<double> u = grid.sample(f);
  ASSERT_EQ(parts<D>(grid.mesh, u, true), 2u);
  EXPECT_GT(drop<D>(grid, u, on_a), 0u);
  EXPECT_EQ(parts<D>(grid.mesh, u, true), 1u);
  for (std::size_t v = 0; v < u.size(); ++v) {
    const Vec<D>& x = grid.mesh.vertices[v];
    if (ball<D>(x, b, 0.1) < 0.0) {
      EXPECT_GE(u[v], 0.0);  // b's solid is gone
    }
    if (ball<D>(x, a, 0.15) < 0.0) {
      EXPECT_LT(u[v], 0.0);  // a's is not
    }
  }
  // With samples on both, nothing changes.
  Points<D> on_both = on_a;
  add_sphere_points<D>(on_both, b, 0.1, 200, 2);
  u = grid.sample(f);
  EXPECT_EQ(drop<D>(grid, u, on_both), 0u);
  EXPECT_EQ(u, grid.sample(f));
}

TEST(UnsupportedParts, OfTwoBallsTheOneWithoutSamplesGoes3D) { two_balls_keep_the_one_with_data<3>(); }
TEST(UnsupportedParts, OfTwoDiscsTheOneWithoutSamplesGoes2D) { two_balls_keep_the_one_with_data<2>(); }

// D + 1 samples span a volume, D do not: a part is kept from D + 1 samples nearest to it.
TEST(UnsupportedParts, APartNeedsFourSamplesIn3D) {
  const Grid<3> grid;
  const Vec<3> a(0.3, 0.5, 0.5), b(0.72, 0.5, 0.5);
  const auto f = [&](const Vec<3>& x) { return std::min(ball<3>(x, a, 0.15), ball<3>(x, b, 0.1)); };
  for (int n : {3, 4}) {
    Points<3> points;
    add_sphere_points<3>(points, a, 0.15, 300, 3);
    add_sphere_points<3>(points, b, 0.1, n, 4);
    std::vector<double> u = grid.sample(f);
    drop<3>(grid, u, points);
    EXPECT_EQ(parts<3>(grid.mesh, u, true), n == 4 ? 2u : 1u) << n << " samples on the small ball";
  }
}

// A hollow ball: its void stays if samples lie on the inner sphere, and is filled if not.
TEST(UnsupportedParts, AVoidWithoutSamplesIsFilled) {
  const Grid<3> grid;
  const Vec<3> c = Vec<3>::Constant(0.5);
  const auto shell = [&](const Vec<3>& x) { return std::max(ball<3>(x, c, 0.3), -ball<3>(x, c, 0.15)); };
  Points<3> outer;
  add_sphere_points<3>(outer, c, 0.3, 400, 5);
  std::vector<double> u = grid.sample(shell);
  ASSERT_EQ(parts<3>(grid.mesh, u, false), 1u);
  EXPECT_GT(drop<3>(grid, u, outer), 0u);
  EXPECT_EQ(parts<3>(grid.mesh, u, false), 0u);
  EXPECT_EQ(parts<3>(grid.mesh, u, true), 1u);
  Points<3> both = outer;
  add_sphere_points<3>(both, c, 0.15, 200, 6);
  u = grid.sample(shell);
  EXPECT_EQ(drop<3>(grid, u, both), 0u);
  EXPECT_EQ(parts<3>(grid.mesh, u, false), 1u);
}

// Without the mesh (a welded surface): the pieces dropped are the parts' boundaries that
// drop_unsupported_parts removes, so the surface left is the one extracted after it.
template <int D>
void pieces_as_parts(const std::function<double(const Vec<D>&)>& f, const Points<D>& points, std::size_t expected) {
  const Grid<D> grid;
  std::vector<double> u = grid.sample(f);
  LevelSetMesh<D> pieces = extract_zero_level_set(grid.mesh, u);
  pieces.sources.clear();
  EXPECT_EQ(drop_unsupported_pieces<D>(pieces, points), expected);
  drop<D>(grid, u, points);
  const LevelSetMesh<D> parts = extract_zero_level_set(grid.mesh, u);
  ASSERT_EQ(pieces.facets.size(), parts.facets.size());
  const auto sorted = [](const LevelSetMesh<D>& s) {
    std::vector<std::array<double, D>> x(s.vertices.size());
    for (std::size_t i = 0; i < x.size(); ++i) std::copy_n(s.vertices[i].data(), D, x[i].begin());
    std::sort(x.begin(), x.end());
    return x;
  };
  EXPECT_EQ(sorted(pieces), sorted(parts));
}

TEST(UnsupportedParts, PiecesOfASurfaceGoAsTheirParts) {
  const Vec<3> a(0.3, 0.5, 0.5), b(0.72, 0.5, 0.5), c = Vec<3>::Constant(0.5);
  const auto balls = [&](const Vec<3>& x) { return std::min(ball<3>(x, a, 0.15), ball<3>(x, b, 0.1)); };
  Points<3> on_a, on_both;
  add_sphere_points<3>(on_a, a, 0.15, 300, 7);
  on_both = on_a;
  add_sphere_points<3>(on_both, b, 0.1, 4, 8);
  pieces_as_parts<3>(balls, on_a, 1);
  pieces_as_parts<3>(balls, on_both, 0);
  const auto shell = [&](const Vec<3>& x) { return std::max(ball<3>(x, c, 0.3), -ball<3>(x, c, 0.15)); };
  Points<3> outer;
  add_sphere_points<3>(outer, c, 0.3, 400, 9);
  pieces_as_parts<3>(shell, outer, 1);
  Points<2> on_disc;
  add_sphere_points<2>(on_disc, Vec<2>(0.3, 0.5), 0.15, 100, 10);
  pieces_as_parts<2>([](const Vec<2>& x) { return std::min(ball<2>(x, Vec<2>(0.3, 0.5), 0.15), ball<2>(x, Vec<2>(0.72, 0.5), 0.1)); },
                     on_disc, 1);
}

}  // namespace
}  // namespace lsr
