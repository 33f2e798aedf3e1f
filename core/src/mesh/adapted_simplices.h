// SPDX-License-Identifier: BSD-3-Clause
/// @file adapted_simplices.h
/// @brief What the adaptation to a metric keeps of a mesh while it changes it, in 2D and 3D
/// (metric_adaptation_2d.cpp, metric_adaptation_3d.cpp): vertices with their metric and the box
/// faces they lie on, simplices with a ball per vertex, lengths and shapes in the metric.
/// Removed vertices and simplices are marked dead, and dropped by result().
#pragma once

#include "mesh/metric_adaptation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace lsr::detail {

// Rounds stop once one changes the vertex count by less than 2%: past that, each round splits
// and collapses about as many edges as the last (relocation lengthens edges the next round
// splits; a metric read at noisy data points jumps between them) and costs as much as the
// first rounds (the 2% is calibrated: docs/calibration.md).
inline bool settled(Index before, Index now) { return std::abs(double(now - before)) < 0.02 * double(now); }

template <int D>
class AdaptedSimplices {
 public:
  using Simplex = std::array<Index, D + 1>;
  using Edge = std::pair<Index, Index>;

  Index vertices() const { return Index(x_.size()) - dead_vertices_; }

  SimplexMesh<D> result() const {
    SimplexMesh<D> out;
    std::vector<Index> renumber(x_.size(), -1);
    for (std::size_t v = 0; v < x_.size(); ++v) {
      if (dead_[v]) continue;
      renumber[v] = Index(out.vertices.size());
      out.vertices.push_back(x_[v]);
    }
    for (std::size_t t = 0; t < simplices_.size(); ++t) {
      if (!alive_[t]) continue;
      Simplex s = simplices_[t];
      for (Index& v : s) v = renumber[std::size_t(v)];
      out.simplices.push_back(s);
    }
    return out;
  }

 protected:
  // The mesh's vertices (its simplices are the caller's to add).
  AdaptedSimplices(const SimplexMesh<D>& mesh, const MetricField<D>& metric) : metric_(metric) {
    lo_ = hi_ = mesh.vertices.empty() ? Vec<D>::Zero() : Vec<D>(mesh.vertices[0]);
    for (const auto& p : mesh.vertices) {
      lo_ = lo_.cwiseMin(p);
      hi_ = hi_.cwiseMax(p);
    }
    for (const auto& p : mesh.vertices) add_vertex(p, faces_of(p));
  }

  // Bits 2k and 2k + 1: on the box's low and high face of axis k.
  unsigned faces_of(const Vec<D>& p) const {
    unsigned f = 0;
    for (int k = 0; k < D; ++k) {
      const double tol = 1e-12 * (hi_[k] - lo_[k]);
      if (p[k] <= lo_[k] + tol) f |= 1u << (2 * k);
      if (p[k] >= hi_[k] - tol) f |= 1u << (2 * k + 1);
    }
    return f;
  }

  Index add_vertex(const Vec<D>& p, unsigned faces) {
    x_.push_back(p);
    m_.push_back(metric_(p));
    faces_.push_back(faces);
    dead_.push_back(0);
    ball_.emplace_back();
    return Index(x_.size()) - 1;
  }
  Index add_simplex(const Simplex& s) {
    const Index t = Index(simplices_.size());
    simplices_.push_back(s);
    alive_.push_back(1);
    for (Index v : s) ball_[std::size_t(v)].push_back(t);
    return t;
  }
  void leave_ball(Index v, Index t) {
    auto& b = ball_[std::size_t(v)];
    const auto it = std::find(b.begin(), b.end(), t);
    *it = b.back();
    b.pop_back();
  }

  double length(Index a, Index b) const {
    return metric_length<D>(x_[std::size_t(b)] - x_[std::size_t(a)], m_[std::size_t(a)], m_[std::size_t(b)]);
  }
  // The shape of s in the mean of its vertices' metrics; x_[moved] read as `at` if given.
  double quality(const Simplex& s, Index moved = -1, const Vec<D>& at = Vec<D>::Zero()) const {
    std::array<Vec<D>, D + 1> p;
    Metric<D> m = Metric<D>::Zero();
    for (std::size_t i = 0; i < D + 1; ++i) {
      const auto v = std::size_t(s[i]);
      p[i] = s[i] == moved ? at : x_[v];
      m += m_[v] / double(D + 1);
    }
    return metric_quality(p, m);
  }
  static bool contains(const Simplex& s, Index v) { return std::find(s.begin(), s.end(), v) != s.end(); }

  // Of `edges`, those longer than kLongEdge, longest first (`longer`), or shorter than
  // kShortEdge, shortest first.
  std::vector<Edge> out_of_bounds(const std::vector<Edge>& edges, bool longer) const {
    std::vector<std::pair<double, Edge>> picked;
    for (const Edge& e : edges) {
      const double l = length(e.first, e.second);
      if (longer ? l > kLongEdge : l < kShortEdge) picked.emplace_back(longer ? -l : l, e);
    }
    std::sort(picked.begin(), picked.end());
    std::vector<Edge> out;
    out.reserve(picked.size());
    for (const auto& p : picked) out.push_back(p.second);
    return out;
  }

  // The mean of the points at unit length from each of v's neighbours `around` on the way to v,
  // kept on the box faces v lies on.
  Vec<D> unit_length_target(Index v, const std::vector<Index>& around) const {
    const auto vi = std::size_t(v);
    Vec<D> target = Vec<D>::Zero();
    for (Index w : around) {
      const Vec<D>& q = x_[std::size_t(w)];
      target += q + (x_[vi] - q) / std::max(length(w, v), 1e-12);
    }
    target /= double(around.size());
    for (int k = 0; k < D; ++k) {
      if (faces_[vi] & (3u << (2 * k))) target[k] = x_[vi][k];
    }
    return target;
  }

  // v moved all, half or a quarter of the way to `target`, the first that raises the worst shape
  // of its ball above `before` (by 0.1%); false if none does.
  bool move_towards(Index v, const Vec<D>& target, double before) {
    const auto vi = std::size_t(v);
    for (double step = 1.0; step > 0.1; step *= 0.5) {
      const Vec<D> p = x_[vi] + step * (target - x_[vi]);
      double after = std::numeric_limits<double>::infinity();
      for (Index t : ball_[vi]) after = std::min(after, quality(simplices_[std::size_t(t)], v, p));
      if (after > before * (1.0 + 1e-3)) {
        x_[vi] = p;
        m_[vi] = metric_(p);
        return true;
      }
    }
    return false;
  }

  const MetricField<D>& metric_;
  Vec<D> lo_, hi_;
  std::vector<Vec<D>> x_;
  std::vector<Metric<D>> m_;
  std::vector<unsigned> faces_;
  std::vector<char> dead_;
  Index dead_vertices_ = 0;
  std::vector<std::vector<Index>> ball_;
  std::vector<Simplex> simplices_;
  std::vector<char> alive_;
};

}  // namespace lsr::detail
