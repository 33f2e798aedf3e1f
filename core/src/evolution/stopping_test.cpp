// SPDX-License-Identifier: BSD-3-Clause
/// @file stopping_test.cpp
#include "evolution/stopping_test.h"

#include <algorithm>
#include <cmath>

namespace lsr::detail {

template <int D>
std::vector<double> data_residuals(const std::vector<Location<D>>& at, const Eigen::VectorXd& u, const std::vector<double>& eps) {
  std::vector<double> r(at.size());
  for (std::size_t i = 0; i < at.size(); ++i) r[i] = std::abs(interpolate(at[i], u)) / eps[i];
  return r;
}

template <int D>
double max_front_distance(const LevelSetMesh<D>& front, const Eigen::VectorXd& d, const Eigen::VectorXd& tolerance,
                          const std::vector<char>& ignored) {
  const auto at = [&](Index v) { return ignored.empty() || !ignored[std::size_t(v)] ? d[v] : 0.0; };
  double worst = 0.0;
  for (const EdgePoint& e : front.sources) {
    worst = std::max(worst, std::abs((1.0 - e.t) * at(e.a) + e.t * at(e.b)) / ((1.0 - e.t) * tolerance[e.a] + e.t * tolerance[e.b]));
  }
  return worst;
}

template <int D>
double median_on_data(const std::vector<Location<D>>& at, const Eigen::VectorXd& u) {
  std::vector<double> values;
  values.reserve(at.size());
  for (const auto& loc : at) values.push_back(interpolate(loc, u));
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

template std::vector<double> data_residuals<2>(const std::vector<Location<2>>& at, const Eigen::VectorXd& u, const std::vector<double>& eps);
template std::vector<double> data_residuals<3>(const std::vector<Location<3>>& at, const Eigen::VectorXd& u, const std::vector<double>& eps);
template double max_front_distance<2>(const LevelSetMesh<2>& front, const Eigen::VectorXd& d, const Eigen::VectorXd& tolerance,
                          const std::vector<char>& ignored);
template double max_front_distance<3>(const LevelSetMesh<3>& front, const Eigen::VectorXd& d, const Eigen::VectorXd& tolerance,
                          const std::vector<char>& ignored);
template double median_on_data<2>(const std::vector<Location<2>>& at, const Eigen::VectorXd& u);
template double median_on_data<3>(const std::vector<Location<3>>& at, const Eigen::VectorXd& u);

}  // namespace lsr::detail
