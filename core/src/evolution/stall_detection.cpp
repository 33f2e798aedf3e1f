// SPDX-License-Identifier: BSD-3-Clause
/// @file stall_detection.cpp
#include "evolution/stall_detection.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace lsr {

bool StallDetector::stalled(double best_residual, bool improved, double displacement, double bulk) {
  best_.push_back(best_residual);
  // The bulk's residual alternates with the renormalisations: its best so far.
  bulk_.push_back(bulk_.empty() ? bulk : std::min(bulk, bulk_.back()));
  displacement_.push_back(displacement);
  since_improvement_ = improved ? 0 : since_improvement_ + 1;
  if (since_improvement_ >= rule_.patience) return true;
  const std::size_t n = best_.size(), p = std::size_t(rule_.patience);
  if (n <= p) return false;
  const double swept = std::accumulate(displacement_.end() - long(p), displacement_.end(), 0.0);
  if (!(swept < rule_.stillness)) return false;
  const double start = best_[n - 1 - p];
  const bool bulk_crept = bulk_.back() > 0.0 && bulk_.back() >= (1.0 - rule_.gain) * bulk_[n - 1 - p];
  return best_residual >= (1.0 - rule_.gain) * start || start <= rule_.near || bulk_crept;
}

double bulk_residual(std::vector<double> residuals, double bulk_share) {
  if (residuals.empty()) return 0.0;
  const auto rank = residuals.begin() + long(bulk_share * double(residuals.size() - 1));
  std::nth_element(residuals.begin(), rank, residuals.end());
  return *rank;
}

template <>
double front_measure<2>(const LevelSetMesh<2>& front) {
  double sum = 0.0;
  for (const auto& f : front.facets) sum += (front.vertices[f[1]] - front.vertices[f[0]]).norm();
  return sum;
}

template <>
double front_measure<3>(const LevelSetMesh<3>& front) {
  double sum = 0.0;
  for (const auto& f : front.facets) {
    sum += 0.5 * (front.vertices[f[1]] - front.vertices[f[0]]).cross(front.vertices[f[2]] - front.vertices[f[0]]).norm();
  }
  return sum;
}

double front_displacement(const Eigen::VectorXd& before, const Eigen::VectorXd& after, const Eigen::VectorXd& ball_measure,
                          const Eigen::VectorXd& spacing, int dimension, double front_measure) {
  if (!(front_measure > 0.0)) return std::numeric_limits<double>::infinity();
  double swept = 0.0;
  for (Eigen::Index v = 0; v < after.size(); ++v) {
    if ((before[v] < 0.0) != (after[v] < 0.0)) swept += ball_measure[v] / spacing[v];
  }
  return swept / (dimension + 1) / front_measure;
}

}  // namespace lsr
