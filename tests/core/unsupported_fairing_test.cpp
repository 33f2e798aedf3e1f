// SPDX-License-Identifier: BSD-3-Clause
/// @file unsupported_fairing_test.cpp
/// @brief The fairing of unsupported vertices against the analytic solution: on a periodic
/// triangulated grid (every vertex of degree 6) a wave along the grid is an eigenvector of the
/// graph Laplacian L with the eigenvalue l = 4 (1 - cos(2 pi / w)), so one implicit step of
/// (I + t L^2) damps it by exactly 1 / (1 + t l^2).
#include "surface/unsupported_fairing.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lsr {
namespace {

constexpr double kPi = 3.14159265358979323846;

// An n x n grid closed into a torus: each square split along its (1, 1) diagonal, so each
// vertex has the neighbours (+-1, 0), (0, +-1) and +-(1, 1). Heights `z(i, j)`.
template <class Height>
LevelSetMesh<3> periodic_grid(int n, const Height& z) {
  LevelSetMesh<3> s;
  const auto id = [n](int i, int j) { return Index(((i + n) % n) * n + (j + n) % n); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) s.vertices.push_back(Vec<3>(i, j, z(i, j)));
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      s.facets.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.facets.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return s;
}

// Only the heights are looked at: the grid's x and y are not periodic, only its graph is.
TEST(UnsupportedFairing, DampsEachWaveByItsEigenvalue) {
  const int n = 32;
  const double step = 16.0;
  for (const int w : {2, 4, 8, 16, 32}) {
    const auto wave = [&](int i, int) { return std::cos(2.0 * kPi * i / w); };
    LevelSetMesh<3> s = periodic_grid(n, wave);
    EXPECT_EQ(fair_unsupported(s, edge_graph(s), std::vector<char>(s.vertices.size(), 1), step), s.vertices.size());
    const double l = 4.0 * (1.0 - std::cos(2.0 * kPi / w));
    const double damping = 1.0 / (1.0 + step * l * l);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const Vec<3>& x = s.vertices[std::size_t(i * n + j)];
        EXPECT_NEAR(x.z(), damping * wave(i, j), 1e-12) << "w " << w;
      }
    }
  }
}

TEST(UnsupportedFairing, FixedVerticesStayAndFreeOnesSolveTheirRows) {
  const int n = 16;
  const double step = 16.0;
  const auto bumps = [](int i, int j) { return std::sin(1.3 * i) * std::cos(0.7 * j) + 0.25 * ((i + j) % 2); };
  const LevelSetMesh<3> before = periodic_grid(n, bumps);
  LevelSetMesh<3> s = before;
  std::vector<char> free(s.vertices.size(), 0);
  for (int i = 3; i < 11; ++i) {
    for (int j = 2; j < 9; ++j) free[std::size_t(i * n + j)] = 1;
  }
  EXPECT_EQ(fair_unsupported(s, edge_graph(s), free, step), 56u);
  // Row v: x_v + t (L (L x))_v = x0_v, (L y)_v = 6 y_v - the sum over its six neighbours.
  const int di[6] = {1, -1, 0, 0, 1, -1}, dj[6] = {0, 0, 1, -1, 1, -1};
  const auto laplacian = [&](const std::vector<Vec<3>>& y) {
    std::vector<Vec<3>> out(y.size());
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        Vec<3> sum = 6.0 * y[std::size_t(i * n + j)];
        for (int k = 0; k < 6; ++k) sum -= y[std::size_t(((i + di[k] + n) % n) * n + (j + dj[k] + n) % n)];
        out[std::size_t(i * n + j)] = sum;
      }
    }
    return out;
  };
  const std::vector<Vec<3>> x(s.vertices.begin(), s.vertices.end());
  const std::vector<Vec<3>> llx = laplacian(laplacian(x));
  for (std::size_t v = 0; v < x.size(); ++v) {
    if (!free[v]) {
      EXPECT_EQ(s.vertices[v], before.vertices[v]);
    } else {
      EXPECT_LT((x[v] + step * llx[v] - before.vertices[v]).norm(), 1e-10);
    }
  }
}

// Growth by hysteresis: from one seed, over every allowed vertex joined to it by edges, and no
// farther (a band of allowed rows apart from the seed's stays as it was).
TEST(UnsupportedFairing, GrowsOverAllowedVerticesJoinedByEdges) {
  const int n = 16;
  const LevelSetMesh<3> s = periodic_grid(n, [](int, int) { return 0.0; });
  std::vector<char> flags(s.vertices.size(), 0), allowed(s.vertices.size(), 0);
  const auto row = [n](std::size_t v) { return int(v) / n; };
  for (std::size_t v = 0; v < allowed.size(); ++v) allowed[v] = (row(v) >= 3 && row(v) <= 10) || row(v) == 13 || row(v) == 14;
  flags[std::size_t(5 * n + 5)] = 1;
  flags[std::size_t(0 * n + 7)] = 1;  // a seed that is not itself allowed stays, alone
  grow_over_edges(edge_graph(s), flags, allowed);
  for (std::size_t v = 0; v < flags.size(); ++v) {
    const bool expected = (row(v) >= 3 && row(v) <= 10) || v == std::size_t(7);
    EXPECT_EQ(bool(flags[v]), expected) << "vertex " << v;
  }
}

TEST(UnsupportedFairing, NoFreeVertexMovesNothing) {
  LevelSetMesh<3> s = periodic_grid(8, [](int i, int j) { return double(i * j); });
  const LevelSetMesh<3> before = s;
  EXPECT_EQ(fair_unsupported(s, edge_graph(s), std::vector<char>(s.vertices.size(), 0), 16.0), 0u);
  EXPECT_EQ(s.vertices, before.vertices);
}

}  // namespace
}  // namespace lsr
