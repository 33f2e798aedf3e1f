// SPDX-License-Identifier: BSD-3-Clause
/// @file pinning.cpp
#include "evolution/pinning.h"

namespace lsr::detail {

VertexCells pin_cells(const Eigen::VectorXd& scale, std::size_t points, const std::vector<double>& d,
                      const std::vector<Index>& nearest, double pin_factor) {
  std::vector<char> in(d.size(), 0);
  for (std::size_t v = 0; v < d.size(); ++v) in[v] = d[v] <= pin_factor * scale[v];
  VertexCells c;
  c.offsets.assign(points + 1, 0);
  for (std::size_t v = 0; v < d.size(); ++v) c.offsets[nearest[v] + 1] += in[v];
  for (std::size_t i = 0; i < points; ++i) c.offsets[i + 1] += c.offsets[i];
  c.vertices.resize(c.offsets[points]);
  std::vector<Index> fill(c.offsets.begin(), c.offsets.end() - 1);
  for (std::size_t v = 0; v < d.size(); ++v) {
    if (in[v]) c.vertices[fill[nearest[v]]++] = Index(v);
  }
  return c;
}

template <int D>
void pin_reached_data(const std::vector<Location<D>>& at, const VertexCells& cells,
                      const Eigen::VectorXd& u, double alpha, const std::vector<double>& reach,
                      std::vector<char>& pinned, Eigen::VectorXd& d, std::vector<char>& held) {
  auto hold = [&](Index vertex) {
    d[vertex] = 0.0;
    held[vertex] = 1;
  };
  for (std::size_t i = 0; i < at.size(); ++i) {
    if (pinned[i]) continue;
    const double v = interpolate(at[i], u);
    if ((alpha > 0.0 ? v : -v) >= -reach[i]) {
      pinned[i] = 1;
      for (Index vertex : at[i].vertices) hold(vertex);
      for (Index k = cells.offsets[i]; k < cells.offsets[i + 1]; ++k) hold(cells.vertices[k]);
    }
  }
}

template void pin_reached_data<2>(const std::vector<Location<2>>& at, const VertexCells& cells,
                      const Eigen::VectorXd& u, double alpha, const std::vector<double>& reach,
                      std::vector<char>& pinned, Eigen::VectorXd& d, std::vector<char>& held);
template void pin_reached_data<3>(const std::vector<Location<3>>& at, const VertexCells& cells,
                      const Eigen::VectorXd& u, double alpha, const std::vector<double>& reach,
                      std::vector<char>& pinned, Eigen::VectorXd& d, std::vector<char>& held);

}  // namespace lsr::detail
