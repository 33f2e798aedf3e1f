// SPDX-License-Identifier: BSD-3-Clause
/// @file data_preparation.cpp
#include "sampling/data_preparation.h"

#include "lsrecon/core/errors.h"
#include "lsrecon/core/reconstruction_options.h"
#include "sampling/exact_duplicates.h"
#include "sampling/point_validation.h"
#include "sampling/z_order.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace lsr::detail {

template <int D>
void require_spanning(const Points<D>& points) {
  Vec<D> mean = Vec<D>::Zero();
  for (const auto& p : points) mean += p / double(points.size());
  double extent = 0.0;
  for (const auto& p : points) extent = std::max(extent, (p - mean).cwiseAbs().maxCoeff());
  // Scaled to the extent: squares of 1e300 would overflow.
  Eigen::Matrix<double, D, D> cov = Eigen::Matrix<double, D, D>::Zero();
  if (extent > 0.0 && std::isfinite(extent)) {
    for (const auto& p : points) cov += ((p - mean) / extent) * ((p - mean) / extent).transpose();
  }
  require_spread<D>(points.size(), mean, extent, cov);
}

template <int D>
void require_spread(std::size_t distinct, const Vec<D>& mean, double extent, const Eigen::Matrix<double, D, D>& cov) {
  const char* shape = D == 2 ? "closed curve" : "closed surface";
  if (distinct == 0) {
    throw InvalidInput("the point set is empty (no finite points)", "pass a cloud with points; NaN / infinite points are skipped");
  }
  if (distinct < std::size_t(D + 1)) {
    throw InvalidInput(std::to_string(distinct) + " distinct point(s) cannot define a " + shape,
                       "pass at least " + std::to_string(D + 1) + " distinct points; a useful "
                       "reconstruction needs hundreds");
  }
  if (!std::isfinite(extent) || !mean.allFinite()) {
    throw InvalidInput("the coordinates are too large for double precision arithmetic",
                       "rescale the points (coordinates below 1e150)");
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> eig(cov);
  const double largest = eig.eigenvalues()[D - 1];
  // Relative thickness below 1e-6: flat to double precision after any realistic noise.
  if (!(largest > 0.0) || eig.eigenvalues()[0] < 1e-12 * largest) {
    std::ostringstream why;
    why << "the points are " << (D == 2 ? "colinear" : "coplanar or colinear") << " (thinner than 1e-6 of their extent "
        << std::setprecision(3) << extent << "): they do not enclose a region";
    throw InvalidInput(why.str(),
                       D == 3 ? "planar points give closed curves: reconstruct them in 2D (reconstruct<2>; setDimension(2) in the "
                                "PCL class; an .svg or .txt output in the command line)"
                              : "a closed curve needs points that are not on one line");
  }
}

template <int D>
bool drop_isolated(const LocalSampling<D>& s, double factor, Points<D>& points, std::vector<std::size_t>& kept) {
  if (factor <= 0.0) return false;
  std::size_t n = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (s.gap[i] > factor * s.spacing[i]) continue;
    points[n] = points[i];
    kept[n++] = kept[i];
  }
  if (n == points.size()) return false;
  points.resize(n);
  kept.resize(n);
  return true;
}

template <int D>
std::vector<double> local_scales(const LocalSampling<D>& s) {
  std::vector<double> l(s.spacing.size());
  for (std::size_t i = 0; i < l.size(); ++i) l[i] = std::max({s.spacing[i], 1.5 * s.noise[i], 1e-9});
  return l;
}

template <int D>
std::vector<double> local_mesh_sizes(const std::vector<double>& scale, double fixed, double max_resolution) {
  const double lo = 1.0 / (max_resolution > 0.0 ? max_resolution : automatic_defaults(D).max_resolution);
  const double hi = std::max(lo, automatic_defaults(D).coarsest_finest_size);
  std::vector<double> h(scale.size());
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = fixed > 0.0 ? fixed : std::clamp(scale[i], lo, hi);
  return h;
}

template <int D>
void in_z_order(const UnitBoxTransform<D>& box, Points<D>& points, std::vector<std::size_t>& kept) {
  const std::vector<Index> order = z_order<D>(box.to_unit(points));
  Points<D> sorted(points.size());
  std::vector<std::size_t> sorted_kept(kept.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    sorted[i] = points[std::size_t(order[i])];
    sorted_kept[i] = kept[std::size_t(order[i])];
  }
  points = std::move(sorted);
  kept = std::move(sorted_kept);
}

template <int D>
DataPoints<D> distinct_finite_points(const Points<D>& input) {
  DataPoints<D> out;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (input[i].allFinite()) out.finite.push_back(i);
  }
  DistinctPoints<D> distinct = merge_exact_duplicates(drop_non_finite(input));
  out.points = std::move(distinct.points);
  out.kept.resize(distinct.first.size());
  for (std::size_t i = 0; i < out.kept.size(); ++i) out.kept[i] = out.finite[distinct.first[i]];
  out.first.resize(out.finite.size());
  for (std::size_t i = 0; i < out.finite.size(); ++i) out.first[i] = out.finite[distinct.first[distinct.index_of[i]]];
  return out;
}

template <int D>
Points<D> DataPoints<D>::input_normals(const Points<D>& normals, std::size_t input) const {
  Points<D> out(input, Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (std::size_t i = 0; i < kept.size(); ++i) out[kept[i]] = normals[i];
  for (std::size_t i = 0; i < finite.size(); ++i) out[finite[i]] = out[first[i]];
  return out;
}

template struct DataPoints<2>;
template struct DataPoints<3>;
template DataPoints<2> distinct_finite_points<2>(const Points<2>&);
template DataPoints<3> distinct_finite_points<3>(const Points<3>&);
template void require_spanning<2>(const Points<2>& points);
template void require_spanning<3>(const Points<3>& points);
template void require_spread<2>(std::size_t, const Vec<2>&, double, const Eigen::Matrix<double, 2, 2>&);
template void require_spread<3>(std::size_t, const Vec<3>&, double, const Eigen::Matrix<double, 3, 3>&);
template bool drop_isolated<2>(const LocalSampling<2>& s, double factor, Points<2>& points, std::vector<std::size_t>& kept);
template bool drop_isolated<3>(const LocalSampling<3>& s, double factor, Points<3>& points, std::vector<std::size_t>& kept);
template std::vector<double> local_scales<2>(const LocalSampling<2>& s);
template std::vector<double> local_scales<3>(const LocalSampling<3>& s);
template std::vector<double> local_mesh_sizes<2>(const std::vector<double>& scale, double fixed, double max_resolution);
template std::vector<double> local_mesh_sizes<3>(const std::vector<double>& scale, double fixed, double max_resolution);
template void in_z_order<2>(const UnitBoxTransform<2>& box, Points<2>& points, std::vector<std::size_t>& kept);
template void in_z_order<3>(const UnitBoxTransform<3>& box, Points<3>& points, std::vector<std::size_t>& kept);

}  // namespace lsr::detail
