// SPDX-License-Identifier: BSD-3-Clause
/// @file drives.cpp
#include "evolution/drives.h"

#include "start/tangent_discs.h"

#include <algorithm>

namespace lsr::detail {

template <int D>
Eigen::VectorXd two_sided_drive(const P1Operators<D>& ops, const Eigen::VectorXd& d, const Points<D>& away,
                                const Eigen::VectorXd& u) {
  const Eigen::VectorXd g = ops.gradient_times(u);
  Eigen::VectorXd drive(d.size());
  for (Eigen::Index v = 0; v < d.size(); ++v) {
    const Vec<D> gv = g.template segment<D>(D * v);
    const double norm = gv.norm();
    drive[v] = norm > 0.0 ? d[v] * away[std::size_t(v)].dot(gv) / norm : 0.0;
  }
  return drive;
}

template <int D>
Eigen::VectorXd drive_resting_past_data(const P1Operators<D>& ops, const Eigen::VectorXd& d, const Points<D>& away,
                                        const Eigen::VectorXd& u, const std::vector<double>& dist, const Eigen::VectorXd& gap,
                                        const std::vector<char>& near_hole, double alpha) {
  Eigen::VectorXd drive = two_sided_drive(ops, d, away, u);
  for (Eigen::Index v = 0; v < drive.size(); ++v) {
    const bool passed = alpha * drive[v] < 0.0 && dist[std::size_t(v)] > gap[v];
    drive[v] = passed && (near_hole.empty() || !near_hole[std::size_t(v)]) ? 0.0 : d[v];
  }
  return drive;
}

template <int D>
Attraction attraction(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, const SimplexMesh<D>& mesh,
                      const std::vector<double>& dist, const Eigen::VectorXd& distance, const Eigen::VectorXd& scale,
                      double gap_factor, double hole_radius, bool rims_only, int threads) {
  Attraction a;
  a.d = distance;
  if (!(hole_radius > 0.0)) return a;
  const std::size_t nv = mesh.vertices.size();
  std::vector<double> cap(nv);
  for (std::size_t v = 0; v < nv; ++v) cap[v] = (2.0 * gap_factor + 1.0) * scale[v] + hole_radius;
  const std::vector<double> discs = tangent_disc_distance(data, sampling, hole_radius, mesh.vertices, dist, cap, threads, rims_only);
  a.over_hole.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) a.over_hole[v] = discs[v] < dist[v];
  for (std::size_t v = 0; v < nv; ++v) {
    a.d[v] = std::min(dist[v], discs[v] + std::max(0.0, gap_factor * scale[v] - dist[v]));
  }
  return a;
}

template Attraction attraction<2>(const NearestPointIndex<2>&, const LocalSampling<2>&, const SimplexMesh<2>&,
                                  const std::vector<double>&, const Eigen::VectorXd&, const Eigen::VectorXd&, double, double,
                                  bool, int);
template Attraction attraction<3>(const NearestPointIndex<3>&, const LocalSampling<3>&, const SimplexMesh<3>&,
                                  const std::vector<double>&, const Eigen::VectorXd&, const Eigen::VectorXd&, double, double,
                                  bool, int);
template Eigen::VectorXd two_sided_drive<2>(const P1Operators<2>& ops, const Eigen::VectorXd& d, const Points<2>& away,
                                const Eigen::VectorXd& u);
template Eigen::VectorXd two_sided_drive<3>(const P1Operators<3>& ops, const Eigen::VectorXd& d, const Points<3>& away,
                                const Eigen::VectorXd& u);
template Eigen::VectorXd drive_resting_past_data<2>(const P1Operators<2>& ops, const Eigen::VectorXd& d, const Points<2>& away,
                                        const Eigen::VectorXd& u, const std::vector<double>& dist, const Eigen::VectorXd& gap,
                                        const std::vector<char>& near_hole, double alpha);
template Eigen::VectorXd drive_resting_past_data<3>(const P1Operators<3>& ops, const Eigen::VectorXd& d, const Points<3>& away,
                                        const Eigen::VectorXd& u, const std::vector<double>& dist, const Eigen::VectorXd& gap,
                                        const std::vector<char>& near_hole, double alpha);

}  // namespace lsr::detail
