// SPDX-License-Identifier: BSD-3-Clause
/// @file metric_adaptation_2d.cpp
/// @brief Triangles adapted to a metric by local operations (Frey and George, "Mesh
/// generation", chapter 21): every round splits the edges longer than sqrt(2), collapses those
/// shorter than 1/sqrt(2), flips edges where the pair's worse shape improves and moves each
/// vertex towards the points at unit length from its neighbours. Every operation checks the
/// elements it makes: none is inverted or flat, none worse than the worse of the ones it
/// replaces or a fair shape, and a collapse makes no edge longer than sqrt(2).
#include "mesh/metric_adaptation.h"

#include "mesh/adapted_simplices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace lsr {

template <int D>
double metric_length(const Vec<D>& e, const Metric<D>& ma, const Metric<D>& mb) {
  const double la = std::sqrt(std::max(0.0, e.dot(ma * e)));
  const double lb = std::sqrt(std::max(0.0, e.dot(mb * e)));
  if (!(la > 0.0 && lb > 0.0) || std::abs(la - lb) < 1e-6 * (la + lb)) return 0.5 * (la + lb);
  return (la - lb) / std::log(la / lb);
}

double metric_quality(const std::array<Vec<2>, 3>& x, const Metric<2>& m) {
  const Vec<2> e0 = x[1] - x[0], e1 = x[2] - x[1], e2 = x[0] - x[2];
  const double area = 0.5 * (e2.x() * e0.y() - e2.y() * e0.x());  // (x1 - x0) x (x2 - x0) / 2
  const double sum = e0.dot(m * e0) + e1.dot(m * e1) + e2.dot(m * e2);
  if (!(sum > 0.0)) return 0.0;
  return 4.0 * std::sqrt(3.0) * area * std::sqrt(std::max(0.0, m.determinant())) / sum;
}

namespace {

using Triangle = detail::AdaptedSimplices<2>::Simplex;
using Edge = std::pair<Index, Index>;

// A collapse or a relocation may leave elements this good even where the ones they replace
// were better: a fair triangle (angles within about 20-130 degrees in the metric).
constexpr double kFairQuality = 0.3;
// Split passes a round before the flips and moves repair the shapes: splitting the same thin
// triangles pass after pass flattens some to zero area.
constexpr int kSplitPasses = 2;

class TriangleAdaptation : public detail::AdaptedSimplices<2> {
 public:
  TriangleAdaptation(const SimplexMesh<2>& mesh, const MetricField<2>& metric) : AdaptedSimplices<2>(mesh, metric) {
    for (const auto& s : mesh.simplices) add_simplex(s);
  }

  // The edges longer than sqrt(2), longest first, in kSplitPasses passes.
  Index split_long_edges() {
    Index n = 0;
    for (int pass = 0; pass < kSplitPasses; ++pass) {
      const std::vector<Edge> longer = out_of_bounds(edges(), true);
      if (longer.empty()) break;
      for (const Edge& e : longer) {
        if (shared(e.first, e.second).empty()) continue;  // split already, as a neighbour's side
        n += split(e.first, e.second) ? 1 : 0;
      }
    }
    return n;
  }

  Index collapse_short_edges() {
    Index n = 0;
    for (const auto& [a, b] : out_of_bounds(edges(), false)) {
      if (dead_[std::size_t(a)] || dead_[std::size_t(b)] || shared(a, b).empty() || length(a, b) >= kShortEdge) continue;
      if (collapse(a, b) || collapse(b, a)) ++n;
    }
    return n;
  }

  // Until no flip improves: after the first sweep only the sides of flipped pairs are looked at
  // again. Each flip raises the worse quality of its pair, so it ends.
  Index flip_edges() {
    Index n = 0;
    std::vector<Edge> work = edges();
    while (!work.empty()) {
      std::vector<Edge> next;
      for (const Edge& e : work) {
        Index c = -1, d = -1;
        if (!flip(e.first, e.second, c, d)) continue;
        ++n;
        for (const Edge& side : {Edge(e.first, c), Edge(c, e.second), Edge(e.second, d), Edge(d, e.first)}) next.push_back(side);
      }
      work = std::move(next);
    }
    return n;
  }

  Index relocate_vertices() {
    Index n = 0;
    for (Index v = 0; v < Index(x_.size()); ++v) n += relocate(v) ? 1 : 0;
    return n;
  }

 private:
  static bool corner(unsigned faces) { return (faces & 3u) != 0 && (faces & 12u) != 0; }

  // Every edge once: an inner edge from the triangle that runs it from its lower vertex, an
  // edge of the box from its only triangle.
  std::vector<Edge> edges() const {
    std::vector<Edge> e;
    e.reserve(2 * simplices_.size());
    for (std::size_t t = 0; t < simplices_.size(); ++t) {
      if (!alive_[t]) continue;
      const Triangle& s = simplices_[t];
      for (int i = 0; i < 3; ++i) {
        const Index a = s[std::size_t(i)], b = s[std::size_t((i + 1) % 3)];
        if (a < b) {
          e.emplace_back(a, b);
        } else if (shared(a, b).size() == 1) {
          e.emplace_back(b, a);
        }
      }
    }
    return e;
  }

  static Index third(const Triangle& s, Index a, Index b) {
    for (Index v : s) {
      if (v != a && v != b) return v;
    }
    return -1;
  }
  // The triangles on edge ab: at most two in a conforming mesh.
  struct Pair {
    std::array<Index, 2> t{};
    std::size_t n = 0;
    bool empty() const { return n == 0; }
    std::size_t size() const { return n; }
    const Index* begin() const { return t.data(); }
    const Index* end() const { return t.data() + n; }
  };
  Pair shared(Index a, Index b) const {
    Pair out;
    for (Index t : ball_[std::size_t(a)]) {
      if (out.n < 2 && contains(simplices_[std::size_t(t)], b)) out.t[out.n++] = t;
    }
    return out;
  }
  // The vertices sharing an edge with v, ascending, into `out` (reused: no allocation per call).
  void neighbours(Index v, std::vector<Index>& out) const {
    out.clear();
    for (Index t : ball_[std::size_t(v)]) {
      for (Index w : simplices_[std::size_t(t)]) {
        if (w != v) out.push_back(w);
      }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  // At the midpoint, unless rounding would leave a half flat.
  bool split(Index a, Index b) {
    const Pair around = shared(a, b);
    const Vec<2> m = 0.5 * (x_[std::size_t(a)] + x_[std::size_t(b)]);
    for (Index t : around) {
      const Triangle& s = simplices_[std::size_t(t)];
      const Vec<2> p = x_[std::size_t(third(s, a, b))];
      const auto area = [&](const Vec<2>& u, const Vec<2>& v) { return (u - p).x() * (v - p).y() - (u - p).y() * (v - p).x(); };
      if (!(std::abs(area(x_[std::size_t(a)], m)) > 0.0 && std::abs(area(m, x_[std::size_t(b)])) > 0.0)) return false;
    }
    const Index c = add_vertex(m, faces_[std::size_t(a)] & faces_[std::size_t(b)]);
    for (Index t : around) {
      Triangle half = simplices_[std::size_t(t)];
      std::replace(half.begin(), half.end(), a, c);
      std::replace(simplices_[std::size_t(t)].begin(), simplices_[std::size_t(t)].end(), b, c);
      leave_ball(b, t);
      ball_[std::size_t(c)].push_back(t);
      add_simplex(half);
    }
    return true;
  }

  // Removes a, moving its triangles to b, if the mesh stays valid and fair.
  bool collapse(Index a, Index b) {
    const unsigned fa = faces_[std::size_t(a)], fb = faces_[std::size_t(b)];
    if ((fa & ~fb) != 0) return false;  // a may only slide along its faces
    const Pair around = shared(a, b);
    // The link condition: a and b share no neighbour but the triangles' third vertices.
    neighbours(a, na_);
    neighbours(b, nb_);
    std::size_t common = 0;
    for (auto i = na_.begin(), j = nb_.begin(); i != na_.end() && j != nb_.end();) {
      if (*i < *j) {
        ++i;
      } else if (*j < *i) {
        ++j;
      } else {
        ++common, ++i, ++j;
      }
    }
    if (common != around.size()) return false;
    for (Index v : na_) {
      if (v != b && length(b, v) > kLongEdge) return false;
    }
    double before = std::numeric_limits<double>::infinity(), after = before;
    for (Index t : ball_[std::size_t(a)]) {
      const Triangle& s = simplices_[std::size_t(t)];
      before = std::min(before, quality(s));
      if (!contains(s, b)) after = std::min(after, quality(s, a, x_[std::size_t(b)]));
    }
    if (!(after > 0.0) || after < std::min(before, kFairQuality)) return false;
    moved_ = ball_[std::size_t(a)];
    for (Index t : moved_) {
      Triangle& s = simplices_[std::size_t(t)];
      if (contains(s, b)) {
        alive_[std::size_t(t)] = 0;
        for (Index v : s) {
          if (v != a) leave_ball(v, t);
        }
      } else {
        std::replace(s.begin(), s.end(), a, b);
        ball_[std::size_t(b)].push_back(t);
      }
    }
    ball_[std::size_t(a)].clear();
    dead_[std::size_t(a)] = 1;
    ++dead_vertices_;
    return true;
  }

  // Replaces the diagonal ab of the quadrilateral acbd by cd if the worse triangle improves.
  bool flip(Index a, Index b, Index& c_out, Index& d_out) {
    const Pair around = shared(a, b);
    if (around.size() != 2) return false;
    Index t1 = around.t[0], t2 = around.t[1];
    // t1 = (a, b, c) in its orientation, t2 = (b, a, d).
    const Triangle& s1 = simplices_[std::size_t(t1)];
    const auto ia = std::size_t(std::find(s1.begin(), s1.end(), a) - s1.begin());
    if (s1[(ia + 1) % 3] != b) std::swap(t1, t2);
    const Index c = third(simplices_[std::size_t(t1)], a, b), d = third(simplices_[std::size_t(t2)], a, b);
    if (!shared(c, d).empty()) return false;
    const Triangle n1{c, a, d}, n2{c, d, b};
    const double before = std::min(quality(simplices_[std::size_t(t1)]), quality(simplices_[std::size_t(t2)]));
    const double after = std::min(quality(n1), quality(n2));
    if (!(after > before * (1.0 + 1e-3) + 1e-12)) return false;
    simplices_[std::size_t(t1)] = n1;
    simplices_[std::size_t(t2)] = n2;
    leave_ball(a, t2);
    leave_ball(b, t1);
    ball_[std::size_t(c)].push_back(t2);
    ball_[std::size_t(d)].push_back(t1);
    c_out = c;
    d_out = d;
    return true;
  }

  // Towards the mean of the points at unit length from each neighbour on the way to v.
  bool relocate(Index v) {
    const auto vi = std::size_t(v);
    if (dead_[vi] || corner(faces_[vi])) return false;
    neighbours(v, na_);
    const Vec<2> target = unit_length_target(v, na_);
    double before = std::numeric_limits<double>::infinity();
    for (Index t : ball_[vi]) before = std::min(before, quality(simplices_[std::size_t(t)]));
    return move_towards(v, target, before);
  }

  std::vector<Index> na_, nb_, moved_;  // scratch lists, reused
};

}  // namespace

SimplexMesh<2> adapt_to_metric(const SimplexMesh<2>& mesh, const MetricField<2>& metric, int max_cycles,
                               MetricAdaptationStats* stats) {
  TriangleAdaptation work(mesh, metric);
  MetricAdaptationStats s;
  for (; s.cycles < max_cycles;) {
    ++s.cycles;
    const Index before = work.vertices();
    const Index split = work.split_long_edges(), collapsed = work.collapse_short_edges();
    s.splits += split;
    s.collapses += collapsed;
    s.flips += work.flip_edges();
    s.moves += work.relocate_vertices();
    if (detail::settled(before, work.vertices())) break;
  }
  s.flips += work.flip_edges();
  if (stats) *stats = s;
  return work.result();
}

template double metric_length<2>(const Vec<2>&, const Metric<2>&, const Metric<2>&);
template double metric_length<3>(const Vec<3>&, const Metric<3>&, const Metric<3>&);

}  // namespace lsr
