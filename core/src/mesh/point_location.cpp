// SPDX-License-Identifier: BSD-3-Clause
/// @file point_location.cpp
/// @brief Point location by descent of the Kuhn bisection forest.
#include "mesh/point_location.h"

#include "thread_count.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <omp.h>

namespace lsr {

template <int D>
Location<D> locate(const AdaptiveMesh<D>& mesh, const Vec<D>& p, double tolerance) {
  const auto& forest = mesh.forest;
  Location<D> at;
  if (!p.allFinite()) return at;
  const int n = forest.cells_per_axis();
  std::array<double, D> y{};
  Index cell = 0;
  for (int d = D - 1; d >= 0; --d) {
    if (p[d] < -tolerance || p[d] > 1.0 + tolerance) return at;
    const double x = std::clamp(p[d], 0.0, 1.0) * n;
    const int c = std::min(int(x), n - 1);
    y[d] = x - c;
    cell = cell * n + c;
  }
  // The Kuhn simplex of the cell holding y orders the axes by decreasing local coordinate.
  std::array<int, D> order{};
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return y[a] > y[b]; });
  const auto& perms = KuhnBisectionForest<D>::permutations();
  const int perm = int(std::find(perms.begin(), perms.end(), order) - perms.begin());
  std::array<double, D + 1> w{};
  w[0] = 1.0 - y[order[0]];
  for (int k = 1; k < D; ++k) w[k] = y[order[k - 1]] - y[order[k]];
  w[D] = y[order[D - 1]];

  // Descend: bisection at z = (x0 + xg)/2 sends p to the child holding x0 when w0 >= wg.
  // Rewriting x0 = 2z - xg (or xg = 2z - x0) updates the weights exactly.
  Index s = forest.root(cell, perm);
  const auto& nodes = forest.simplices();
  while (!forest.is_leaf(s)) {
    const int g = nodes[s].tag;
    if (w[0] >= w[g]) {
      w[0] -= w[g];
      w[g] *= 2.0;
      s = nodes[s].first_child;
    } else {
      const double w0 = w[0];
      for (int k = 0; k < g - 1; ++k) w[k] = w[k + 1];
      w[g - 1] = w[g] - w0;
      w[g] = 2.0 * w0;
      s = nodes[s].first_child + 1;
    }
  }
  at.simplex = mesh.simplex_of_node[s];
  for (int k = 0; k <= D; ++k) at.vertices[k] = mesh.vertex_of_node_vertex[std::size_t(nodes[s].v[k])];
  at.weights = w;
  return at;
}

template <int D>
std::vector<Location<D>> locate_all(const AdaptiveMesh<D>& mesh, const Points<D>& points,
                                    int threads) {
  std::vector<Location<D>> out(points.size());
  const long n = long(points.size());
#pragma omp parallel for schedule(static) num_threads(detail::thread_count(threads))
  for (long i = 0; i < n; ++i) out[i] = locate(mesh, points[i]);
  return out;
}

template Location<2> locate<2>(const AdaptiveMesh<2>&, const Vec<2>&, double);
template Location<3> locate<3>(const AdaptiveMesh<3>&, const Vec<3>&, double);
template std::vector<Location<2>> locate_all<2>(const AdaptiveMesh<2>&, const Points<2>&, int);
template std::vector<Location<3>> locate_all<3>(const AdaptiveMesh<3>&, const Points<3>&, int);

}  // namespace lsr
