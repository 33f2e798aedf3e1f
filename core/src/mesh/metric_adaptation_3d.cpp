// SPDX-License-Identifier: BSD-3-Clause
/// @file metric_adaptation_3d.cpp
/// @brief Tetrahedra adapted to a metric by local operations, the 2D file's rounds in 3D (Frey
/// and George, "Mesh generation", chapter 21): edges longer than sqrt(2) split, edges shorter
/// than 1/sqrt(2) collapsed, 2-3 and 3-2 swaps where the worse shape improves, vertices moved
/// towards the points at unit length from their neighbours. Every operation checks the
/// tetrahedra it makes: none inverted or flat, none worse than the worse of the ones it replaces
/// or a fair shape (a split's halves: or kSplitFloor). A collapse needs no link test beyond
/// that: the new tetrahedra are cones from the kept vertex over the removed vertex's link,
/// which fill its ball exactly when all are positive (the ball is then star-shaped from the
/// kept vertex).
#include "mesh/metric_adaptation.h"

#include "mesh/adapted_simplices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace lsr {

double metric_quality(const std::array<Vec<3>, 4>& x, const Metric<3>& m) {
  const Vec<3> e[6] = {x[1] - x[0], x[2] - x[0], x[3] - x[0], x[2] - x[1], x[3] - x[1], x[3] - x[2]};
  double sum = 0.0;
  for (const Vec<3>& d : e) sum += d.dot(m * d);
  if (!(sum > 0.0)) return 0.0;
  const double volume = e[0].dot(e[1].cross(e[2])) / 6.0 * std::sqrt(std::max(0.0, m.determinant()));
  const double root = std::cbrt(3.0 * std::abs(volume));
  const double q = 12.0 * root * root / sum;
  return volume < 0.0 ? -q : q;
}

namespace {

using Tet = detail::AdaptedSimplices<3>::Simplex;
using Edge = std::pair<Index, Index>;

// As in 2D: the shape a collapse or a relocation may always reach, and the split passes a round.
constexpr double kFairQuality = 0.3;
constexpr int kSplitPasses = 2;
// A split's halves are at least as good as their tetrahedron or this (split()).
constexpr double kSplitFloor = 0.05;

// Swaps and relocations are tried only where a tetrahedron is worse than this: most of a unit
// mesh is better, and trying every face and edge took 2/3 of the time, relocating every vertex
// a third of the rest, for the same surface.
constexpr double kImproveBelow = 0.5;

double volume6(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c, const Vec<3>& d) {
  return (b - a).dot((c - a).cross(d - a));
}

class TetAdaptation : public detail::AdaptedSimplices<3> {
 public:
  TetAdaptation(const SimplexMesh<3>& mesh, const MetricField<3>& metric) : AdaptedSimplices<3>(mesh, metric) {
    for (const auto& s : mesh.simplices) add_tet(s);
  }

  Index split_long_edges() {
    Index n = 0;
    for (int pass = 0; pass < kSplitPasses; ++pass) {
      const std::vector<Edge> longer = out_of_bounds(edges(), true);
      if (longer.empty()) break;
      for (const Edge& e : longer) {
        shell(e.first, e.second, shell_);
        if (shell_.empty()) continue;  // split already, as a neighbour's edge
        n += split(e.first, e.second) ? 1 : 0;
      }
    }
    return n;
  }

  Index collapse_short_edges() {
    Index n = 0;
    for (const auto& [a, b] : out_of_bounds(edges(), false)) {
      if (dead_[std::size_t(a)] || dead_[std::size_t(b)] || length(a, b) >= kShortEdge) continue;
      shell(a, b, shell_);
      if (shell_.empty()) continue;
      if (collapse(a, b) || collapse(b, a)) ++n;
    }
    return n;
  }

  // 3-2 swaps on the edges of three tetrahedra, then 2-3 swaps on the faces, of the tetrahedra
  // worse than kImproveBelow, each where the worse shape improves, until a sweep swaps less
  // than 1% of the tetrahedra (each swap raises the worse shape of its group, so it ends).
  Index swap() {
    Index n = 0;
    for (int sweep = 0; sweep < 8; ++sweep) {
      Index k = 0;
      const std::size_t tets = simplices_.size();
      for (std::size_t t = 0; t < tets; ++t) {
        if (!alive_[t] || q_[t] >= kImproveBelow) continue;
        const Tet s = simplices_[t];
        for (int i = 0; i < 4 && alive_[t]; ++i) {
          for (int j = i + 1; j < 4 && alive_[t]; ++j) k += swap32(s[std::size_t(i)], s[std::size_t(j)]) ? 1 : 0;
        }
      }
      for (std::size_t t = 0; t < tets; ++t) {
        for (int f = 0; f < 4 && alive_[t]; ++f) k += swap23(Index(t), f) ? 1 : 0;
      }
      n += k;
      if (double(k) < 0.01 * double(simplices_.size() - std::size_t(dead_simplices_))) break;
    }
    return n;
  }

  Index relocate_vertices() {
    Index n = 0;
    for (Index v = 0; v < Index(x_.size()); ++v) n += relocate(v) ? 1 : 0;
    return n;
  }

 private:
  Index add_tet(const Tet& s) {
    q_.push_back(quality(s));
    return add_simplex(s);
  }
  void remove_tet(Index t) {
    alive_[std::size_t(t)] = 0;
    ++dead_simplices_;
    for (Index v : simplices_[std::size_t(t)]) leave_ball(v, t);
  }

  // Every edge once, from its lower vertex, in the order of the vertices.
  std::vector<Edge> edges() {
    std::vector<Edge> e;
    e.reserve(x_.size() * 8);
    stamp_.resize(x_.size(), 0);
    for (Index v = 0; v < Index(x_.size()); ++v) {
      for (Index t : ball_[std::size_t(v)]) {
        for (Index w : simplices_[std::size_t(t)]) {
          if (w > v && stamp_[std::size_t(w)] != v + 1) {
            stamp_[std::size_t(w)] = v + 1;
            e.emplace_back(v, w);
          }
        }
      }
    }
    std::fill(stamp_.begin(), stamp_.end(), 0);
    return e;
  }

  double volume(const Tet& s) const {
    return volume6(x_[std::size_t(s[0])], x_[std::size_t(s[1])], x_[std::size_t(s[2])], x_[std::size_t(s[3])]);
  }

  // The tetrahedra around edge ab, into `out`.
  void shell(Index a, Index b, std::vector<Index>& out) const {
    out.clear();
    for (Index t : ball_[std::size_t(a)]) {
      if (contains(simplices_[std::size_t(t)], b)) out.push_back(t);
    }
  }
  // The vertices sharing an edge with v, into `out` (reused: no allocation per call).
  void neighbours(Index v, std::vector<Index>& out) {
    out.clear();
    stamp_.resize(x_.size(), 0);
    for (Index t : ball_[std::size_t(v)]) {
      for (Index w : simplices_[std::size_t(t)]) {
        if (w != v && stamp_[std::size_t(w)] != v + 1) {
          stamp_[std::size_t(w)] = v + 1;
          out.push_back(w);
        }
      }
    }
    for (Index w : out) stamp_[std::size_t(w)] = 0;
  }

  // At the midpoint, unless rounding would leave a half flat.
  bool split(Index a, Index b) {
    const Vec<3> m = 0.5 * (x_[std::size_t(a)] + x_[std::size_t(b)]);
    for (Index t : shell_) {
      Tet half_a = simplices_[std::size_t(t)], half_b = half_a;
      std::replace(half_a.begin(), half_a.end(), a, Index(-1));
      std::replace(half_b.begin(), half_b.end(), b, Index(-1));
      const auto at = [&](Index v) { return v < 0 ? m : Vec<3>(x_[std::size_t(v)]); };
      if (!(volume6(at(half_a[0]), at(half_a[1]), at(half_a[2]), at(half_a[3])) > 0.0) ||
          !(volume6(at(half_b[0]), at(half_b[1]), at(half_b[2]), at(half_b[3])) > 0.0)) {
        return false;
      }
      // Each half as good as its tetrahedron or kSplitFloor (read in the metric of the vertex
      // it replaces): without that, splits in a metric that jumps between data points
      // flatten the same tetrahedra round after round.
      const Tet& s = simplices_[std::size_t(t)];
      const double keep = std::min(q_[std::size_t(t)], kSplitFloor);
      if (quality(s, a, m) < keep || quality(s, b, m) < keep) return false;
    }
    const Index c = add_vertex(m, faces_[std::size_t(a)] & faces_[std::size_t(b)]);
    for (Index t : shell_) {
      Tet half = simplices_[std::size_t(t)];
      std::replace(half.begin(), half.end(), a, c);
      Tet& s = simplices_[std::size_t(t)];
      std::replace(s.begin(), s.end(), b, c);
      q_[std::size_t(t)] = quality(s);
      leave_ball(b, t);
      ball_[std::size_t(c)].push_back(t);
      add_tet(half);
    }
    return true;
  }

  // Removes a, moving its tetrahedra to b, if they stay positive and fair.
  bool collapse(Index a, Index b) {
    const unsigned fa = faces_[std::size_t(a)], fb = faces_[std::size_t(b)];
    if ((fa & ~fb) != 0) return false;  // a may only slide along its faces
    neighbours(a, na_);
    for (Index v : na_) {
      if (v != b && length(b, v) > kLongEdge) return false;
    }
    double before = std::numeric_limits<double>::infinity(), after = before;
    for (Index t : ball_[std::size_t(a)]) {
      const Tet& s = simplices_[std::size_t(t)];
      before = std::min(before, q_[std::size_t(t)]);
      if (contains(s, b)) continue;
      Tet moved = s;
      std::replace(moved.begin(), moved.end(), a, b);
      if (!(volume(moved) > 0.0)) return false;
      after = std::min(after, quality(s, a, x_[std::size_t(b)]));
    }
    if (!(after > 0.0) || after < std::min(before, kFairQuality)) return false;
    moved_ = ball_[std::size_t(a)];
    for (Index t : moved_) {
      Tet& s = simplices_[std::size_t(t)];
      if (contains(s, b)) {
        remove_tet(t);
      } else {
        std::replace(s.begin(), s.end(), a, b);
        q_[std::size_t(t)] = quality(s);
        ball_[std::size_t(b)].push_back(t);
      }
    }
    ball_[std::size_t(a)].clear();
    dead_[std::size_t(a)] = 1;
    ++dead_vertices_;
    return true;
  }

  // The three tetrahedra around an inner edge ab become two on the triangle of their other
  // vertices, if the worse shape improves.
  bool swap32(Index a, Index b) {
    if (dead_[std::size_t(a)] || dead_[std::size_t(b)]) return false;
    shell(a, b, shell_);
    if (shell_.size() != 3) return false;
    ring_.clear();
    double before = std::numeric_limits<double>::infinity();
    for (Index t : shell_) {
      before = std::min(before, q_[std::size_t(t)]);
      for (Index v : simplices_[std::size_t(t)]) {
        if (v != a && v != b && std::find(ring_.begin(), ring_.end(), v) == ring_.end()) ring_.push_back(v);
      }
    }
    if (ring_.size() != 3 || before >= kImproveBelow) return false;  // an open shell is on the box
    Tet top{ring_[0], ring_[1], ring_[2], a};
    if (volume(top) < 0.0) std::swap(top[0], top[1]);
    const Tet bottom{top[1], top[0], top[2], b};
    if (!(volume(top) > 0.0 && volume(bottom) > 0.0)) return false;
    if (!(std::min(quality(top), quality(bottom)) > before * (1.0 + 1e-3) + 1e-12)) return false;
    for (Index t : shell_) remove_tet(t);
    add_tet(top);
    add_tet(bottom);
    return true;
  }

  // The two tetrahedra on face f of t (the face opposite its vertex f) become three around the
  // edge joining their apexes, if the edge crosses the face and the worse shape improves;
  // looked at from the side of a bad t.
  bool swap23(Index t, int f) {
    const Tet s = simplices_[std::size_t(t)];
    if (q_[std::size_t(t)] >= kImproveBelow) return false;
    const Index a = s[std::size_t((f + 1) % 4)], b = s[std::size_t((f + 2) % 4)], c = s[std::size_t((f + 3) % 4)];
    Index other = -1;
    for (Index u : ball_[std::size_t(a)]) {
      const Tet& w = simplices_[std::size_t(u)];
      if (u != t && contains(w, b) && contains(w, c)) {
        other = u;
        break;
      }
    }
    if (other < 0) return false;  // on the box
    Index e = -1;
    for (Index v : simplices_[std::size_t(other)]) {
      if (v != a && v != b && v != c) e = v;
    }
    // Each new tetrahedron is s with one vertex of the face replaced by e.
    std::array<Tet, 3> made{s, s, s};
    for (std::size_t i = 0; i < 3; ++i) made[i][std::size_t((f + 1 + int(i)) % 4)] = e;
    double after = std::numeric_limits<double>::infinity();
    for (const Tet& n : made) {
      if (!(volume(n) > 0.0)) return false;
      after = std::min(after, quality(n));
    }
    const double before = std::min(q_[std::size_t(t)], q_[std::size_t(other)]);
    if (!(after > before * (1.0 + 1e-3) + 1e-12)) return false;
    remove_tet(t);
    remove_tet(other);
    for (const Tet& n : made) add_tet(n);
    return true;
  }

  // Towards the mean of the points at unit length from each neighbour on the way to v, along
  // the box faces it lies on.
  bool relocate(Index v) {
    const auto vi = std::size_t(v);
    if (dead_[vi]) return false;
    double before = std::numeric_limits<double>::infinity();
    for (Index t : ball_[vi]) before = std::min(before, q_[std::size_t(t)]);
    if (before >= kImproveBelow) return false;
    neighbours(v, na_);
    const Vec<3> target = unit_length_target(v, na_);
    if (target == x_[vi]) return false;
    if (!move_towards(v, target, before)) return false;
    for (Index t : ball_[vi]) q_[std::size_t(t)] = quality(simplices_[std::size_t(t)]);
    return true;
  }

  std::vector<Index> stamp_;  // per vertex: the last vertex + 1 whose edges listed it
  std::vector<double> q_;     // per tetrahedron: its quality, kept up to date
  Index dead_simplices_ = 0;
  std::vector<Index> na_, moved_, shell_, ring_;  // scratch lists, reused
};

}  // namespace

SimplexMesh<3> adapt_to_metric(const SimplexMesh<3>& mesh, const MetricField<3>& metric, int max_cycles,
                               MetricAdaptationStats* stats) {
  TetAdaptation work(mesh, metric);
  MetricAdaptationStats s;
  for (; s.cycles < max_cycles;) {
    ++s.cycles;
    const Index before = work.vertices();
    const Index split = work.split_long_edges();
    const Index collapsed = work.collapse_short_edges();
    s.splits += split;
    s.collapses += collapsed;
    s.flips += work.swap();
    s.moves += work.relocate_vertices();
    const Index now = work.vertices();
    if (detail::settled(before, now)) break;
  }
  s.flips += work.swap();
  if (stats) *stats = s;
  return work.result();
}

}  // namespace lsr
