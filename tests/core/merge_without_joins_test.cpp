// SPDX-License-Identifier: BSD-3-Clause
/// @file merge_without_joins_test.cpp
/// @brief Simple vertices, and a merge that moves a zero set without changing its topology:
/// analytic signed distances on a uniform Kuhn mesh, judged by the extracted surface's genus
/// and the components of the sign sets.
#include "fit/merge_without_joins.h"
#include "lsrecon/core/level_set_extraction.h"
#include "mesh/adaptive_refinement.h"
#include "mesh/kuhn_bisection.h"
#include "start/outside_flood_fill.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

namespace lsr {
namespace {

// Positively oriented, as the pipeline's meshes are: the extraction orients facets by them.
template <int D>
SimplexMesh<D> uniform_mesh(int cells) {
  return leaf_mesh(KuhnBisectionForest<D>(cells)).mesh;
}

template <int D>
Eigen::VectorXd sample(const SimplexMesh<D>& mesh, const std::function<double(const Vec<D>&)>& f) {
  Eigen::VectorXd u(Eigen::Index(mesh.vertices.size()));
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) u[Eigen::Index(v)] = f(mesh.vertices[v]);
  return u;
}

std::vector<double> as_vector(const Eigen::VectorXd& u) { return std::vector<double>(u.data(), u.data() + u.size()); }

template <int D>
std::size_t negative_parts(const SimplexMesh<D>& mesh, const std::vector<double>& u) {
  std::vector<char> member(u.size());
  for (std::size_t v = 0; v < u.size(); ++v) member[v] = u[v] < 0.0;
  const std::vector<Index> root = vertex_components(mesh, member);
  std::set<Index> roots(root.begin(), root.end());
  roots.erase(-1);
  return roots.size();
}

std::vector<int> genus_of(const SimplexMesh<3>& mesh, const std::vector<double>& u) {
  const LevelSetMesh<3> s = extract_zero_level_set(mesh, u);
  const SurfaceTopology t = analyze_surface(s.vertices, s.facets);
  EXPECT_TRUE(t.watertight && t.vertex_manifold);
  std::vector<int> genus = t.genus;
  std::sort(genus.begin(), genus.end());
  return genus;
}

const Vec<3> kCentre = Vec<3>::Constant(0.5);

double ball(const Vec<3>& x, const Vec<3>& c, double r) { return (x - c).norm() - r; }

// Solid torus around the z axis through the centre: radii R (of the core circle) and r.
double torus(const Vec<3>& x, double R, double r) {
  const Vec<3> d = x - kCentre;
  return std::hypot(std::hypot(d.x(), d.y()) - R, d.z()) - r;
}

std::vector<Index> star_of(const SimplexMesh<3>& mesh, Index v) {
  std::vector<Index> star;
  for (Index s = 0; s < Index(mesh.simplices.size()); ++s) {
    const auto& t = mesh.simplices[std::size_t(s)];
    if (std::find(t.begin(), t.end(), v) != t.end()) star.push_back(s);
  }
  return star;
}

TEST(MergeWithoutJoins, LinkPiecesOfAFlatFrontAndOfAnIsolatedVertex) {
  const SimplexMesh<3> mesh = uniform_mesh<3>(8);
  const auto at_centre = [](const Vec<3>& x) { return (x - kCentre).norm() < 1e-12; };
  const Index centre = Index(std::find_if(mesh.vertices.begin(), mesh.vertices.end(), at_centre) - mesh.vertices.begin());
  ASSERT_LT(std::size_t(centre), mesh.vertices.size());
  const std::vector<Index> star = star_of(mesh, centre);
  std::vector<char> negative(mesh.vertices.size());
  // Below a plane through the centre: one piece on each side, the centre is simple.
  for (std::size_t v = 0; v < negative.size(); ++v) negative[v] = mesh.vertices[v].z() < 0.5 + 1e-9;
  LinkPieces p = link_pieces(mesh, star, centre, negative);
  EXPECT_EQ(p.negative, 1);
  EXPECT_EQ(p.non_negative, 1);
  EXPECT_TRUE(p.simple());
  // A slab one vertex thick: the centre's link has two positive caps; emptying it would
  // punch a hole through the slab.
  for (std::size_t v = 0; v < negative.size(); ++v) negative[v] = std::abs(mesh.vertices[v].z() - 0.5) < 1e-9;
  p = link_pieces(mesh, star, centre, negative);
  EXPECT_EQ(p.negative, 1);
  EXPECT_EQ(p.non_negative, 2);
  EXPECT_FALSE(p.simple());
  // All neighbours positive: the centre is a component of its own.
  std::fill(negative.begin(), negative.end(), 0);
  negative[std::size_t(centre)] = 1;
  p = link_pieces(mesh, star, centre, negative);
  EXPECT_EQ(p.negative, 0);
  EXPECT_EQ(p.non_negative, 1);
}

TEST(MergeWithoutJoins, MovesAFrontWhereNoTopologyChanges) {
  // A sphere grown from radius 0.25 to 0.3 (two cells): every vertex in between may flip.
  const SimplexMesh<3> mesh = uniform_mesh<3>(40);
  const Eigen::VectorXd front = sample<3>(mesh, [](const Vec<3>& x) { return ball(x, kCentre, 0.25); });
  std::vector<double> wanted = as_vector(sample<3>(mesh, [](const Vec<3>& x) { return ball(x, kCentre, 0.3); }));
  const std::vector<double> before = wanted;
  EXPECT_EQ(merge_without_joins(mesh, front, wanted), 0u);
  EXPECT_EQ(wanted, before);
}

// A solid disc around the z axis, and the same disc with the hole of a torus.
double disc(const Vec<3>& x) {
  const Vec<3> d = x - kCentre;
  return std::max(std::abs(d.z()) - 0.06, std::hypot(d.x(), d.y()) - 0.33);
}
double ring(const Vec<3>& x) { return torus(x, 0.25, 0.08); }

TEST(MergeWithoutJoins, DoesNotPunchAHoleThroughADisc) {
  // Wanted: the torus; the disc's middle empties down to a membrane of vertices whose flip
  // would open the hole (genus 0 -> 1), which keep the disc's sign.
  const SimplexMesh<3> mesh = uniform_mesh<3>(40);
  const Eigen::VectorXd front = sample<3>(mesh, disc);
  std::vector<double> wanted = as_vector(sample<3>(mesh, ring));
  ASSERT_EQ(genus_of(mesh, wanted), std::vector<int>{1});
  EXPECT_GT(merge_without_joins(mesh, front, wanted), 0u);
  EXPECT_EQ(genus_of(mesh, wanted), std::vector<int>{0});
  // The middle did empty: most of its vertices took the wanted sign.
  std::size_t middle = 0, emptied = 0;
  for (std::size_t v = 0; v < wanted.size(); ++v) {
    const Vec<3> d = mesh.vertices[v] - kCentre;
    if (std::abs(d.z()) < 0.05 && std::hypot(d.x(), d.y()) < 0.12) {
      ++middle;
      emptied += wanted[v] >= 0.0;
    }
  }
  EXPECT_GT(emptied, middle / 2);
}

TEST(MergeWithoutJoins, PunchesTheHoleWhereJoinsAreAllowed) {
  // Joins allowed in the middle only (where a front far from the data is a guess): the torus.
  const SimplexMesh<3> mesh = uniform_mesh<3>(40);
  const Eigen::VectorXd front = sample<3>(mesh, disc);
  std::vector<double> wanted = as_vector(sample<3>(mesh, ring));
  std::vector<char> may_join(wanted.size());
  for (std::size_t v = 0; v < wanted.size(); ++v) {
    const Vec<3> d = mesh.vertices[v] - kCentre;
    may_join[v] = std::hypot(d.x(), d.y()) < 0.1;
  }
  const std::vector<double> before = wanted;
  EXPECT_EQ(merge_without_joins(mesh, front, wanted, may_join), 0u);
  EXPECT_EQ(wanted, before);
  EXPECT_EQ(genus_of(mesh, wanted), std::vector<int>{1});
}

TEST(MergeWithoutJoins, MaySealATorusHole) {
  // The reverse removes a handle (genus 1 -> 0): every vertex may flip.
  const SimplexMesh<3> mesh = uniform_mesh<3>(40);
  const Eigen::VectorXd front = sample<3>(mesh, ring);
  std::vector<double> wanted = as_vector(sample<3>(mesh, disc));
  const std::vector<double> before = wanted;
  EXPECT_EQ(merge_without_joins(mesh, front, wanted), 0u);
  EXPECT_EQ(wanted, before);
  EXPECT_EQ(genus_of(mesh, wanted), std::vector<int>{0});
}

TEST(MergeWithoutJoins, NeitherBridgesNorCreatesPartsButLetsOneVanish) {
  const SimplexMesh<3> mesh = uniform_mesh<3>(40);
  const Vec<3> a(0.3, 0.5, 0.5), b(0.7, 0.5, 0.5), speck(0.5, 0.8, 0.5);
  const Eigen::VectorXd front = sample<3>(mesh, [&](const Vec<3>& x) {
    return std::min({ball(x, a, 0.15), ball(x, b, 0.15), ball(x, speck, 0.06)});
  });
  ASSERT_EQ(negative_parts(mesh, as_vector(front)), 3u);
  // Wanted: the two balls joined by a bar, a new ball, and no speck.
  std::vector<double> wanted = as_vector(sample<3>(mesh, [&](const Vec<3>& x) {
    const double bar = std::max(std::hypot(x.y() - 0.5, x.z() - 0.5) - 0.05, std::abs(x.x() - 0.5) - 0.2);
    return std::min({ball(x, a, 0.15), ball(x, b, 0.15), bar, ball(x, Vec<3>(0.5, 0.2, 0.5), 0.06)});
  }));
  ASSERT_EQ(negative_parts(mesh, wanted), 2u);
  merge_without_joins(mesh, front, wanted);
  EXPECT_EQ(negative_parts(mesh, wanted), 2u);  // the two balls apart, the speck gone, no new ball
  for (std::size_t v = 0; v < wanted.size(); ++v) {
    if ((mesh.vertices[v] - speck).norm() < 0.04) {
      EXPECT_GE(wanted[v], 0.0) << "speck vertex " << v;
    }
    if ((mesh.vertices[v] - Vec<3>(0.5, 0.2, 0.5)).norm() < 0.04) {
      EXPECT_GE(wanted[v], 0.0) << "new ball vertex " << v;
    }
  }
  EXPECT_EQ(genus_of(mesh, wanted), (std::vector<int>{0, 0}));
}

TEST(MergeWithoutJoins, MayCutABarBetweenTwoBalls) {
  // The reverse of a bridge: the bar empties, the front splits in two (a neck the front has
  // not finished cutting).
  const SimplexMesh<3> mesh = uniform_mesh<3>(40);
  const Vec<3> a(0.3, 0.5, 0.5), b(0.7, 0.5, 0.5);
  const auto balls = [&](const Vec<3>& x) { return std::min(ball(x, a, 0.15), ball(x, b, 0.15)); };
  const Eigen::VectorXd front = sample<3>(mesh, [&](const Vec<3>& x) {
    return std::min(balls(x), std::max(std::hypot(x.y() - 0.5, x.z() - 0.5) - 0.05, std::abs(x.x() - 0.5) - 0.2));
  });
  ASSERT_EQ(negative_parts(mesh, as_vector(front)), 1u);
  std::vector<double> wanted = as_vector(sample<3>(mesh, balls));
  EXPECT_EQ(merge_without_joins(mesh, front, wanted), 0u);
  EXPECT_EQ(negative_parts(mesh, wanted), 2u);
}

TEST(MergeWithoutJoins, KeepsTwoCurvesApartIn2D) {
  // Two discs and a bar joining them, on a triangle mesh: the same rule with a circle as link.
  const SimplexMesh<2> mesh = uniform_mesh<2>(64);
  const Vec<2> a(0.3, 0.5), b(0.7, 0.5);
  const auto discs = [&](const Vec<2>& x) { return std::min((x - a).norm() - 0.15, (x - b).norm() - 0.15); };
  const Eigen::VectorXd front = sample<2>(mesh, discs);
  std::vector<double> wanted = as_vector(sample<2>(mesh, [&](const Vec<2>& x) {
    return std::min(discs(x), std::max(std::abs(x.y() - 0.5) - 0.04, std::abs(x.x() - 0.5) - 0.2));
  }));
  ASSERT_EQ(negative_parts(mesh, wanted), 1u);
  EXPECT_GT(merge_without_joins(mesh, front, wanted), 0u);
  EXPECT_EQ(negative_parts(mesh, wanted), 2u);
  EXPECT_EQ(closed_loops(extract_zero_level_set(mesh, wanted)).size(), 2u);
}

TEST(MergeWithoutJoins, AbsorbsOnlyPartsNarrowerThanTheWidth) {
  // A ball with a bubble of one vertex and a cavity of radius 0.1, and a speck of one vertex
  // outside it: with a width of 2 cells the bubble and the speck go, the cavity stays.
  const SimplexMesh<3> mesh = uniform_mesh<3>(40);
  const double h = 1.0 / 40;
  const Vec<3> bubble(0.5, 0.5, 0.3), speck(0.1, 0.1, 0.1);
  std::vector<double> values = as_vector(sample<3>(mesh, [&](const Vec<3>& x) {
    double f = std::max(ball(x, kCentre, 0.35), -ball(x, Vec<3>(0.5, 0.5, 0.6), 0.1));
    if ((x - bubble).norm() < 1e-9) f = 0.5 * h;
    if ((x - speck).norm() < 1e-9) f = -0.5 * h;
    return f;
  }));
  const Eigen::VectorXd width = Eigen::VectorXd::Constant(Eigen::Index(values.size()), 2.0 * h);
  EXPECT_EQ(absorb_small_parts(mesh, vertex_neighbours(mesh), width, values), 2u);
  EXPECT_EQ(negative_parts(mesh, values), 1u);
  EXPECT_EQ(genus_of(mesh, values), (std::vector<int>{0, 0}));  // the ball and its cavity
}

TEST(MergeWithoutJoins, FillsAVoidItCutOffTheOutsideNotOneTheReferenceEnclosed) {
  // A ball with two cavities: one reached from outside through a tunnel in the reference, one
  // enclosed. The wanted values close the tunnel; the merge may (a cut), leaving a void that
  // nothing in the reference bounded. It is filled; the enclosed cavity stays.
  const SimplexMesh<3> mesh = uniform_mesh<3>(40);
  const Vec<3> reached(0.5, 0.5, 0.65), enclosed(0.5, 0.5, 0.3);
  const auto solid = [&](const Vec<3>& x) {
    return std::max({ball(x, kCentre, 0.35), -ball(x, reached, 0.08), -ball(x, enclosed, 0.08)});
  };
  const Eigen::VectorXd front = sample<3>(mesh, [&](const Vec<3>& x) {
    return std::max(solid(x), -std::max(std::hypot(x.x() - 0.5, x.y() - 0.5) - 0.05, 0.65 - x.z()));
  });
  std::vector<double> values = as_vector(sample<3>(mesh, solid));
  EXPECT_EQ(merge_without_joins(mesh, front, values), 0u);
  ASSERT_EQ(genus_of(mesh, values), (std::vector<int>{0, 0, 0}));
  EXPECT_GT(fill_cut_off_voids(mesh, front, values), 0u);
  EXPECT_EQ(genus_of(mesh, values), (std::vector<int>{0, 0}));
  for (std::size_t v = 0; v < values.size(); ++v) {
    if ((mesh.vertices[v] - reached).norm() < 0.06) {
      EXPECT_LT(values[v], 0.0) << "void vertex " << v;
    }
    if ((mesh.vertices[v] - enclosed).norm() < 0.06) {
      EXPECT_GE(values[v], 0.0) << "cavity vertex " << v;
    }
  }
  // Without a cut there is nothing to fill.
  EXPECT_EQ(fill_cut_off_voids(mesh, sample<3>(mesh, solid), values), 0u);
}

}  // namespace
}  // namespace lsr
