// SPDX-License-Identifier: BSD-3-Clause
/// @file rim_curvature_closure.cpp
#include "surface/rim_curvature_closure.h"

#include "graph/shortest_paths.h"
#include "surface/facet_normals.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace lsr {
namespace {

// The mean curvature of each part's closure, from the balancing of a surface of constant mean
// curvature H: its outward conormal integrated over its boundary equals -2 H (-H in 2D) times
// its vector area, the integral of its normal, which depends on the boundary alone. Closing
// tangent to the seen surface, the conormal is minus the tangent that crosses the boundary
// into the part, in the seen surface's tangent plane. So over the facets S touching the part,
// whose boundary runs through fixed vertices, H = (F . A) / ((D - 1) |A|^2), A the sum of
// their vector areas and F the integral over their boundary of the unit tangent into S.
// Exact on a sphere's cap and a cylinder's strip (docs/how-it-works.md, Unsupported surface).
template <int D>
std::vector<double> balanced_curvature(const LevelSetMesh<D>& s, const EdgeGraph& g, const std::vector<Index>& part, Index parts,
                                       const Points<D>& normals) {
  std::vector<Vec<D>> area(std::size_t(parts), Vec<D>::Zero()), flux(std::size_t(parts), Vec<D>::Zero());
  const auto at_rim = [&](Index v) {
    for (std::size_t k = g.first[std::size_t(v)]; k < g.first[std::size_t(v) + 1]; ++k) {
      if (part[std::size_t(g.next[k])] >= 0) return true;
    }
    return false;
  };
  // The sides (3D: edges, 2D: vertices) of the facets of S and of those beside them: side,
  // its facet's part (-1: not in S) and the facet's vertex opposite the side.
  struct Side {
    std::array<Index, D - 1> vertices;
    Index part;
    Index opposite;
  };
  std::vector<Side> sides;
  for (const auto& f : s.facets) {
    Index p = -1;
    bool near = false;
    for (const Index v : f) {
      p = std::max(p, part[std::size_t(v)]);
      near = near || at_rim(v);
    }
    if (p >= 0) area[std::size_t(p)] += facet_area_normal<D>(s.vertices, f) / double(D - 1);
    if (p < 0 && !near) continue;
    for (int k = 0; k < D; ++k) {
      Side side{{}, p, f[std::size_t(k)]};
      for (int j = 0; j < D - 1; ++j) side.vertices[std::size_t(j)] = f[std::size_t((k + 1 + j) % D)];
      std::sort(side.vertices.begin(), side.vertices.end());
      sides.push_back(side);
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) { return a.vertices < b.vertices || (a.vertices == b.vertices && a.part > b.part); });
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].vertices == sides[i].vertices) ++j;
    // On the boundary of S: a side of one facet of S (first, its part the largest) and one not.
    if (j == i + 2 && sides[i].part >= 0 && sides[i + 1].part < 0) {
      const auto& side = sides[i].vertices;
      const Vec<D>& x = s.vertices[std::size_t(side[0])];
      Vec<D> n = Vec<D>::Zero(), into;
      for (const Index v : side) n += normals[std::size_t(v)];
      n.normalize();
      double length = 1.0;
      if constexpr (D == 3) {
        const Vec<3> along = s.vertices[std::size_t(side[1])] - x;
        length = along.norm();
        into = n.cross(along).normalized();
      } else {
        into = Vec<2>(-n.y(), n.x());
      }
      // Into the part is away from the seen side: the flattened part may lie more than a right
      // angle from where the seen surface heads (an overhang).
      const bool away = into.dot(s.vertices[std::size_t(sides[i + 1].opposite)] - x) <= 0.0;
      flux[std::size_t(sides[i].part)] += (away ? length : -length) * into;
    }
    i = j;
  }
  std::vector<double> h(std::size_t(parts), 0.0);
  for (std::size_t p = 0; p < h.size(); ++p) {
    const double a2 = area[p].squaredNorm();
    if (a2 > 0.0) h[p] = flux[p].dot(area[p]) / (double(D - 1) * a2);
  }
  return h;
}

// Components of the free vertices over the edges between them.
std::vector<Index> free_parts(const EdgeGraph& g, const std::vector<char>& free, Index& parts) {
  std::vector<Index> part(free.size(), -1);
  std::vector<std::size_t> stack;
  parts = 0;
  for (std::size_t v = 0; v < free.size(); ++v) {
    if (!free[v] || part[v] >= 0) continue;
    part[v] = parts;
    stack.push_back(v);
    while (!stack.empty()) {
      const std::size_t a = stack.back();
      stack.pop_back();
      for (std::size_t k = g.first[a]; k < g.first[a + 1]; ++k) {
        const auto w = std::size_t(g.next[k]);
        if (free[w] && part[w] < 0) {
          part[w] = parts;
          stack.push_back(w);
        }
      }
    }
    ++parts;
  }
  return part;
}

// Each free vertex's shortest path over the edges to a fixed vertex (0 at the fixed ones).
template <int D>
std::vector<double> path_to_rim(const LevelSetMesh<D>& s, const EdgeGraph& g, const std::vector<char>& free) {
  std::vector<char> rim(free.size(), 0);
  for (std::size_t v = 0; v < free.size(); ++v) {
    for (std::size_t k = g.first[v]; k < g.first[v + 1] && !free[v] && !rim[v]; ++k) rim[v] = free[std::size_t(g.next[k])];
  }
  std::vector<double> reach = detail::shortest_paths(s.vertices, g.first, g.next, rim, free);
  for (std::size_t v = 0; v < free.size(); ++v) {
    if (!free[v]) reach[v] = 0.0;
  }
  return reach;
}

}  // namespace

template <int D>
RimClosure round_to_rim_curvature(LevelSetMesh<D>& s, const EdgeGraph& g, const std::vector<char>& free, const Points<D>& normals) {
  // The fixed-point iterations stop when one moves no vertex by more than 1e-3 of the first
  // one's largest move, about the depth the front flattened the part by.
  constexpr int kMaxIterations = 20;
  constexpr double kConverged = 1e-3;
  RimClosure out;
  const std::size_t n = s.vertices.size();
  // A part with no rim (a whole component unseen) has nothing to take a curvature from.
  Index parts = 0;
  const std::vector<Index> part = free_parts(g, free, parts);
  const std::vector<double> reach = path_to_rim(s, g, free);
  std::vector<double> inradius(std::size_t(parts), 0.0);
  std::vector<Index> column(n, -1);
  Index unknowns = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (!free[v]) continue;
    inradius[std::size_t(part[v])] = std::max(inradius[std::size_t(part[v])], reach[v]);
    if (std::isfinite(reach[v])) column[v] = unknowns++;
  }
  out.kept = std::size_t(std::count(free.begin(), free.end(), 1)) - std::size_t(unknowns);
  if (unknowns == 0) return out;

  // L = degree - adjacency restricted to the free vertices, the fixed ones on the right.
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t v = 0; v < n; ++v) {
    const Index row = column[v];
    if (row < 0) continue;
    entries.emplace_back(row, row, double(g.first[v + 1] - g.first[v]));
    for (std::size_t k = g.first[v]; k < g.first[v + 1]; ++k) {
      if (column[std::size_t(g.next[k])] >= 0) entries.emplace_back(row, column[std::size_t(g.next[k])], -1.0);
    }
  }
  Eigen::SparseMatrix<double> m(unknowns, unknowns);
  m.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(m);  // positive definite: each part has a rim
  if (solver.info() != Eigen::Success) return RimClosure{0, out.kept + std::size_t(unknowns), 0};
  // Not below 0: a hollow's lid is not drawn in.
  std::vector<double> part_h = balanced_curvature(s, g, part, parts, normals);
  Eigen::VectorXd h(unknowns);
  for (std::size_t v = 0; v < n; ++v) {
    if (column[v] >= 0) h[column[v]] = std::max(0.0, part_h[std::size_t(part[v])]);
  }

  // A part that moves farther than its in-radius (its longest path to the rim) has no closure
  // of that curvature: it keeps its place, and its curvature is dropped so that it stops
  // inflating (parts share no free edge: the others' solutions do not see it).
  std::vector<char> kept(std::size_t(parts), 0);
  const Points<D> before = s.vertices;
  double first_move = 0.0;
  for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
    out.iterations = iteration;
    Points<D> area_normal(n, Vec<D>::Zero());
    for (const auto& f : s.facets) {
      const Vec<D> a = facet_area_normal<D>(s.vertices, f);
      for (const Index i : f) area_normal[std::size_t(i)] += a;
    }
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, D);
    for (std::size_t v = 0; v < n; ++v) {
      const Index row = column[v];
      if (row < 0) continue;
      double squares = 0.0;  // degree * m_v
      for (std::size_t k = g.first[v]; k < g.first[v + 1]; ++k) {
        const auto w = std::size_t(g.next[k]);
        squares += (s.vertices[w] - s.vertices[v]).squaredNorm();
        if (column[w] < 0) rhs.row(row) += s.vertices[w].transpose();
      }
      const double norm = area_normal[v].norm();
      if (norm > 0.0) rhs.row(row) += (squares / 2.0 * h[row] / norm) * area_normal[v].transpose();
    }
    const Eigen::MatrixXd x = solver.solve(rhs);
    std::vector<double> moved(std::size_t(parts), 0.0);
    for (std::size_t v = 0; v < n; ++v) {
      const Index row = column[v];
      if (row < 0) continue;
      const Vec<D> next = x.row(row).transpose();
      const auto p = std::size_t(part[v]);
      moved[p] = next.allFinite() ? std::max(moved[p], (next - before[v]).norm()) : std::numeric_limits<double>::infinity();
    }
    double move = 0.0;
    for (std::size_t v = 0; v < n; ++v) {
      const Index row = column[v];
      if (row < 0) continue;
      const auto p = std::size_t(part[v]);
      kept[p] = kept[p] || !(moved[p] <= inradius[p]);
      const Vec<D> next = kept[p] ? before[v] : Vec<D>(x.row(row).transpose());
      if (kept[p]) h[row] = 0.0;
      move = std::max(move, (next - s.vertices[v]).norm());
      s.vertices[v] = next;
    }
    if (iteration == 1) first_move = move;
    if (move <= kConverged * first_move) break;
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (column[v] >= 0) ++(kept[std::size_t(part[v])] ? out.kept : out.rounded);
  }
  return out;
}

template RimClosure round_to_rim_curvature<2>(LevelSetMesh<2>&, const EdgeGraph&, const std::vector<char>&, const Points<2>&);
template RimClosure round_to_rim_curvature<3>(LevelSetMesh<3>&, const EdgeGraph&, const std::vector<char>&, const Points<3>&);

}  // namespace lsr
