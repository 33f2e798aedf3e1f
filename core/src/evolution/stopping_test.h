// SPDX-License-Identifier: BSD-3-Clause
/// @file stopping_test.h
/// @brief The two sides of the stopping test: the data to the front and the front to the data,
/// in local tolerances.
#pragma once

#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/types.h"
#include "mesh/point_location.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

// Per point |u(x_i)| / eps_i: the data side of the stopping test, in units of the tolerance.
template <int D>
std::vector<double> data_residuals(const std::vector<Location<D>>& at, const Eigen::VectorXd& u, const std::vector<double>& eps);

// Largest distance from the front to the data relative to the local tolerance there (both
// interpolated along the front's source edges): the other side of the stopping test, which
// sees pieces of front far from every data point. d counts as 0 at `ignored` vertices (empty:
// none).
template <int D>
double max_front_distance(const LevelSetMesh<D>& front, const Eigen::VectorXd& d, const Eigen::VectorXd& tolerance,
                          const std::vector<char>& ignored);

template <int D>
double median_on_data(const std::vector<Location<D>>& at, const Eigen::VectorXd& u);

}  // namespace lsr::detail
