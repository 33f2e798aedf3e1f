// SPDX-License-Identifier: BSD-3-Clause
/// @file rim_curvature_closure_test.cpp
/// @brief The closure of unseen parts at their rim's curvature against shapes that satisfy its
/// equations exactly: a regular polygon (2D) and a cylinder triangulated by squares of its own
/// width, each with a part flattened onto its chord as the front leaves an unseen underside.
/// On both the exact shape is the fixed point: each neighbour w of v lies (e . t)^2 / (2 r)
/// below v's tangent plane, t across the cylinder's axis, and the mean over v's neighbours of
/// (e . t)^2 is m_v / 2 (the polygon: m_v), so x_v - mean x_w = (m_v / 2) H n_v with H = 1 / r
/// (polygon) and 1 / (2 r) (cylinder); and the balance of the conormal against the vector area
/// gives that H exactly from the rim's tangents.
#include "surface/rim_curvature_closure.h"

#include "surface/facet_normals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lsr {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The free vertices come back to within this share of the depth they were flattened by: the
// iterations stop when one moves no vertex by more than 1e-3 of the first's largest move,
// which is about that depth, and what remains is the sum of the later moves: at most as much
// again while the moves shrink at least 2x per iteration (measured on these shapes: 4-5x every
// two; the tests below bound the count, 10 iterations for 2^-10 ~ 1e-3).
constexpr double kShareOfDepth = 2e-3;

LevelSetMesh<2> polygon(int n, double r) {
  LevelSetMesh<2> s;
  for (int i = 0; i < n; ++i) s.vertices.push_back(r * Vec<2>(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)));
  for (int i = 0; i < n; ++i) s.facets.push_back({Index(i), Index((i + 1) % n)});  // counter-clockwise: outward normals
  return s;
}

// A regular polygon of n vertices on a circle of radius r, its exact normals, and the `count`
// vertices after vertex `from` (mod n) flattened evenly onto the chord to the next one.
struct FlattenedPolygon {
  LevelSetMesh<2> s;
  Points<2> normals;
  std::vector<char> free;
};

FlattenedPolygon flattened_polygon(int n, double r, int from, int count) {
  FlattenedPolygon p{polygon(n, r), Points<2>(std::size_t(n)), std::vector<char>(std::size_t(n), 0)};
  for (std::size_t v = 0; v < p.normals.size(); ++v) p.normals[v] = p.s.vertices[v].normalized();
  const Vec<2> a = p.s.vertices[std::size_t(from)], b = p.s.vertices[std::size_t((from + count + 1) % n)];
  for (int k = 1; k <= count; ++k) {
    const auto v = std::size_t((from + k) % n);
    p.free[v] = 1;
    p.s.vertices[v] = a + double(k) / double(count + 1) * (b - a);
  }
  return p;
}

TEST(RimCurvatureClosure, AFlattenedArcOfARegularPolygonComesBackOntoItsCircle) {
  const int n = 64;
  const double r = 2.0;
  // Vertices 43 .. 58 (242 .. 326 degrees) flattened onto the chord between 42 and 59.
  const int first = 43, last = 58;
  auto [s, normals, free] = flattened_polygon(n, r, first - 1, last - first + 1);
  double depth = 0.0;
  for (int i = first; i <= last; ++i) depth = std::max(depth, r - s.vertices[std::size_t(i)].norm());
  const RimClosure c = round_to_rim_curvature(s, edge_graph(s), free, normals);
  EXPECT_EQ(c.rounded, std::size_t(last - first + 1));
  EXPECT_EQ(c.kept, 0u);
  EXPECT_LE(c.iterations, 10);  // 1e-3 after at most 10 halvings
  for (int i = first; i <= last; ++i) {
    EXPECT_NEAR(s.vertices[std::size_t(i)].norm(), r, kShareOfDepth * depth) << "vertex " << i;
    const double angle = std::atan2(s.vertices[std::size_t(i)].y(), s.vertices[std::size_t(i)].x()) + 2 * kPi;
    EXPECT_NEAR(angle, 2 * kPi * i / n, 0.05 * 2 * kPi / n) << "vertex " << i;  // evenly spaced again
  }
}

// A cylinder of radius r along x, n vertices round, rows 2 pi r / n apart (squares), each square
// split along a diagonal; outward facets. Rows 0 and rows - 1 are its open ends.
LevelSetMesh<3> cylinder(int n, int rows, double r) {
  LevelSetMesh<3> s;
  const double h = 2 * kPi * r / n;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < n; ++i) s.vertices.push_back(Vec<3>(j * h, r * std::cos(2 * kPi * i / n), r * std::sin(2 * kPi * i / n)));
  }
  const auto id = [n](int i, int j) { return Index(j * n + (i + n) % n); };
  for (int j = 0; j + 1 < rows; ++j) {
    for (int i = 0; i < n; ++i) {
      s.facets.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      s.facets.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
    }
  }
  return s;
}

Vec<3> radial(const Vec<3>& x) { return Vec<3>(0, x.y(), x.z()).normalized(); }

TEST(RimCurvatureClosure, AFlattenedUndersideOfACylinderComesBackOntoItsRadius) {
  const int n = 48, rows = 40;
  const double r = 1.0;
  LevelSetMesh<3> s = cylinder(n, rows, r);
  for (const auto& f : s.facets) {  // the facets face outwards, as the closure's normals assume
    const Vec<3> c = (s.vertices[std::size_t(f[0])] + s.vertices[std::size_t(f[1])] + s.vertices[std::size_t(f[2])]) / 3;
    ASSERT_GT(facet_area_normal<3>(s.vertices, f).dot(radial(c)), 0.0);
  }
  Points<3> normals(s.vertices.size());
  for (std::size_t v = 0; v < normals.size(); ++v) normals[v] = radial(s.vertices[v]);
  // Vertices 25 .. 44 (187.5 .. 330 degrees) of rows 5 .. 34 flattened onto their chord.
  std::vector<char> free(s.vertices.size(), 0);
  const int first = 25, last = 44;
  double depth = 0.0;
  for (int j = 5; j < rows - 5; ++j) {
    const Vec<3> a = s.vertices[std::size_t(j * n + first - 1)], b = s.vertices[std::size_t(j * n + last + 1)];
    for (int i = first; i <= last; ++i) {
      Vec<3>& x = s.vertices[std::size_t(j * n + i)];
      free[std::size_t(j * n + i)] = 1;
      x = a + double(i - first + 1) / double(last - first + 2) * (b - a);
      depth = std::max(depth, r - std::hypot(x.y(), x.z()));
    }
  }
  const RimClosure c = round_to_rim_curvature(s, edge_graph(s), free, normals);
  EXPECT_EQ(c.rounded, std::size_t((rows - 10) * (last - first + 1))) << c.kept << " " << c.iterations;
  EXPECT_LE(c.iterations, 10);
  for (int j = 5; j < rows - 5; ++j) {
    for (int i = first; i <= last; ++i) {
      const Vec<3>& x = s.vertices[std::size_t(j * n + i)];
      EXPECT_NEAR(std::hypot(x.y(), x.z()), r, kShareOfDepth * depth) << "row " << j << " vertex " << i;
    }
  }
}

// A cup's cross-section: a rounded rectangle 4 x 2 with corners of radius 0.2 and its bottom
// side unseen, beyond the corners. The walls come to the rim level (their tangents there
// cross it flat), so the bottom needs no curvature and stays on its line.
TEST(RimCurvatureClosure, AFlatBottomBetweenRoundedCornersStaysFlat) {
  const double half_w = 2.0, half_h = 1.0, rho = 0.2, step = rho * kPi / 2 / 8;
  LevelSetMesh<2> s;
  Points<2> normals;
  std::vector<char> free;
  const auto add = [&](const Vec<2>& x, const Vec<2>& normal, bool unseen) {
    s.vertices.push_back(x);
    normals.push_back(normal);
    free.push_back(unseen);
  };
  const Vec<2> centres[4] = {{half_w - rho, -half_h + rho}, {half_w - rho, half_h - rho}, {-half_w + rho, half_h - rho}, {-half_w + rho, -half_h + rho}};
  for (int k = 0; k < 4; ++k) {  // counter-clockwise from the bottom right corner: outward facets
    for (int a = 0; a < 8; ++a) {  // the corner's quarter arc, its last point left to the side
      const double angle = -kPi / 2 + k * kPi / 2 + a * kPi / 16;
      const Vec<2> radial(std::cos(angle), std::sin(angle));
      add(centres[k] + rho * radial, radial, false);
    }
    const Vec<2> outward(std::cos(k * kPi / 2), std::sin(k * kPi / 2));
    const Vec<2> from = centres[k] + rho * outward, to = centres[(k + 1) % 4] + rho * outward;
    const int pieces = int(std::lround((to - from).norm() / step));
    for (int i = 0; i < pieces; ++i) add(from + double(i) / pieces * (to - from), outward, k == 3 && i > 0);
  }
  for (std::size_t v = 0; v < s.vertices.size(); ++v) s.facets.push_back({Index(v), Index((v + 1) % s.vertices.size())});
  const std::size_t unseen = std::size_t(std::count(free.begin(), free.end(), 1));
  ASSERT_GT(unseen, 80u);
  const LevelSetMesh<2> before = s;
  const RimClosure c = round_to_rim_curvature(s, edge_graph(s), free, normals);
  EXPECT_EQ(c.rounded, unseen);
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    EXPECT_NEAR(s.vertices[v].y(), before.vertices[v].y(), 1e-12) << "vertex " << v;
  }
}

// More than half a circle unseen: two arcs of the circle's curvature (the balance of the rim's
// tangents, pointing outwards and down, gives 1 / r again) pass through the rim, the circle's
// own, 1.5 r below the chord, and its mirror image in the chord, 0.5 r below it. The
// iterations from the flattened part find the nearer: the closure keeps the rim's curvature
// but not its tangents, a crease at the rim instead of an overhang no data shows.
TEST(RimCurvatureClosure, MoreThanHalfACircleUnseenClosesByTheNearerArc) {
  const int n = 96;
  const double r = 2.0;
  // Vertices 41 .. 95 and 0 .. 7 (the 240 degrees from 150 to 30 through the bottom) flattened
  // onto the chord between 40 and 8, at y = r sin(30) = 1.
  const int count = 63;
  const double depth = 0.5 * r;
  auto [s, normals, free] = flattened_polygon(n, r, 40, count);
  const RimClosure c = round_to_rim_curvature(s, edge_graph(s), free, normals);
  EXPECT_EQ(c.rounded, std::size_t(count));
  const Vec<2> mirrored_centre(0.0, 2.0 * r * 0.5);
  for (int k = 1; k <= count; ++k) {
    const Vec<2>& x = s.vertices[std::size_t((40 + k) % n)];
    EXPECT_NEAR((x - mirrored_centre).norm(), r, kShareOfDepth * depth) << "vertex " << (40 + k) % n;
    EXPECT_LT(x.y(), 1.0 + 1e-12);
  }
}

// A whole component unseen has no rim to take a curvature from: it stays as it was.
TEST(RimCurvatureClosure, APartWithNoRimIsKept) {
  LevelSetMesh<2> s = polygon(32, 1.0);
  Points<2> normals(s.vertices.size());
  for (std::size_t v = 0; v < normals.size(); ++v) normals[v] = s.vertices[v];
  const LevelSetMesh<2> before = s;
  const RimClosure c = round_to_rim_curvature(s, edge_graph(s), std::vector<char>(s.vertices.size(), 1), normals);
  EXPECT_EQ(c.rounded, 0u);
  EXPECT_EQ(c.kept, 32u);
  for (std::size_t v = 0; v < s.vertices.size(); ++v) EXPECT_EQ(s.vertices[v], before.vertices[v]);
}

}  // namespace
}  // namespace lsr
