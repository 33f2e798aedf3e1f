// SPDX-License-Identifier: BSD-3-Clause
/// @file unit_box_transform.cpp
#include "sampling/unit_box_transform.h"

#include "lsrecon/core/errors.h"
#include "sampling/point_validation.h"

#include <cmath>
#include <string>

namespace lsr {

template <int D>
UnitBoxTransform<D> UnitBoxTransform<D>::fit(const Points<D>& points, double margin) {
  require_valid_points(points, "unit box fit");
  Vec<D> lo = points[0];
  Vec<D> hi = points[0];
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return fit_bounds(lo, hi, points.size(), margin);
}

template <int D>
UnitBoxTransform<D> UnitBoxTransform<D>::fit_bounds(const Vec<D>& lo, const Vec<D>& hi, std::size_t count, double margin) {
  if (!(margin >= 0.0 && margin < 0.5)) {
    throw InvalidInput("box margin " + std::to_string(margin) + " is outside [0, 0.5)",
                       "use a margin such as 0.1");
  }
  const double extent = (hi - lo).maxCoeff();
  // Relative test: coordinates at 1e6 with a spread of 1e-9 are coincident in double precision.
  const double magnitude = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  if (!(extent > 1e-12 * std::max(1.0, magnitude))) {
    throw InvalidInput("all " + std::to_string(count) + " points coincide",
                       "a reconstruction needs points that span a curve or surface");
  }
  UnitBoxTransform t;
  t.center_ = 0.5 * (lo + hi);
  t.scale_ = (1.0 - 2.0 * margin) / extent;
  return t;
}

template <int D>
UnitBoxTransform<D> UnitBoxTransform<D>::fit_ball(const Points<D>& points, double radius) {
  if (!(radius > 0.0 && radius <= 0.5)) {
    throw InvalidInput("ball radius " + std::to_string(radius) + " is outside (0, 0.5]",
                       "use a radius such as 0.4");
  }
  const UnitBoxTransform t = fit(points, 0.0);  // validates and finds the bounding-box centre
  double reach = 0.0;
  for (const auto& p : points) reach = std::max(reach, (p - t.center_).norm());
  return t.with_ball(reach, radius);
}

template <int D>
UnitBoxTransform<D> UnitBoxTransform<D>::with_ball(double reach, double radius) const {
  UnitBoxTransform t = *this;
  t.scale_ = radius / reach;
  return t;
}

template <int D>
Points<D> UnitBoxTransform<D>::to_unit(const Points<D>& xs) const {
  Points<D> out;
  out.reserve(xs.size());
  for (const auto& x : xs) out.push_back(to_unit(x));
  return out;
}

template <int D>
Points<D> UnitBoxTransform<D>::from_unit(const Points<D>& ys) const {
  Points<D> out;
  out.reserve(ys.size());
  for (const auto& y : ys) out.push_back(from_unit(y));
  return out;
}

template class UnitBoxTransform<2>;
template class UnitBoxTransform<3>;

}  // namespace lsr
