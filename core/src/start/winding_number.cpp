// SPDX-License-Identifier: BSD-3-Clause
/// @file winding_number.cpp
#include "start/winding_number.h"

#include <algorithm>
#include <cmath>

namespace lsr::detail {
namespace {

constexpr int kLeafPoints = 16;
constexpr int kMaxDepth = 40;
// A cell counts as one dipole beyond kFarRatio radii: the first neglected term (the
// quadrupole) is then below (1 / kFarRatio) of the dipole's, a few per cent of w, far below the
// 1/2 that w is compared with.
constexpr double kFarRatio = 3.0;

double dipole_term(const Vec<3>& dipole, const Vec<3>& at, const Vec<3>& x) {
  const Vec<3> e = at - x;
  const double r2 = e.squaredNorm();
  if (r2 == 0.0) return 0.0;
  return dipole.dot(e) / (4.0 * kPi * r2 * std::sqrt(r2));
}

}  // namespace

WindingNumber::WindingNumber(const Points<3>& points, const Points<3>& normals, const std::vector<double>& areas)
    : order_(points.size()), points_(points), dipoles_(points.size()) {
  for (std::size_t p = 0; p < points.size(); ++p) {
    order_[p] = Index(p);
    dipoles_[p] = areas[p] * normals[p];
  }
  if (points.empty()) return;
  cells_.emplace_back();
  build(0, 0, Index(points.size()), 0);
}

void WindingNumber::build(Index id, Index begin, Index end, int depth) {
  Vec<3> lo = Vec<3>::Constant(HUGE_VAL), hi = Vec<3>::Constant(-HUGE_VAL);
  Vec<3> centroid = Vec<3>::Zero(), dipole = Vec<3>::Zero();
  for (Index i = begin; i < end; ++i) {
    const Vec<3>& p = points_[std::size_t(order_[std::size_t(i)])];
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    centroid += p;
    dipole += dipoles_[std::size_t(order_[std::size_t(i)])];
  }
  centroid /= double(end - begin);
  double radius = 0.0;
  for (Index i = begin; i < end; ++i) radius = std::max(radius, (points_[std::size_t(order_[std::size_t(i)])] - centroid).norm());
  Cell cell;
  cell.centroid = centroid;
  cell.dipole = dipole;
  cell.radius = radius;
  cell.begin = begin;
  cell.end = end;
  if (end - begin > kLeafPoints && depth < kMaxDepth && radius > 0.0) {
    // Split at the box's middle along each axis: eight octants, the empty ones dropped.
    const Vec<3> mid = 0.5 * (lo + hi);
    const auto octant = [&](Index p) {
      const Vec<3>& x = points_[std::size_t(p)];
      return int(x[0] > mid[0]) | int(x[1] > mid[1]) << 1 | int(x[2] > mid[2]) << 2;
    };
    std::stable_sort(order_.begin() + begin, order_.begin() + end, [&](Index a, Index b) { return octant(a) < octant(b); });
    std::vector<std::pair<Index, Index>> parts;
    for (Index i = begin; i < end;) {
      Index j = i;
      while (j < end && octant(order_[std::size_t(j)]) == octant(order_[std::size_t(i)])) ++j;
      parts.emplace_back(i, j);
      i = j;
    }
    if (parts.size() > 1) {
      cell.child = Index(cells_.size());  // the children are consecutive
      cell.children = int(parts.size());
      cells_.resize(cells_.size() + parts.size());
      cells_[std::size_t(id)] = cell;
      for (std::size_t k = 0; k < parts.size(); ++k) build(cell.child + Index(k), parts[k].first, parts[k].second, depth + 1);
      return;
    }
  }
  cells_[std::size_t(id)] = cell;
}

double WindingNumber::at(const Vec<3>& x) const {
  double w = 0.0;
  std::vector<Index> stack;
  if (!cells_.empty()) stack.push_back(0);
  while (!stack.empty()) {
    const Cell& c = cells_[std::size_t(stack.back())];
    stack.pop_back();
    if ((c.centroid - x).norm() > kFarRatio * c.radius) {
      w += dipole_term(c.dipole, c.centroid, x);
    } else if (c.child < 0) {
      for (Index i = c.begin; i < c.end; ++i) {
        const auto p = std::size_t(order_[std::size_t(i)]);
        w += dipole_term(dipoles_[p], points_[p], x);
      }
    } else {
      for (int k = 0; k < c.children; ++k) stack.push_back(c.child + k);
    }
  }
  return w;
}

}  // namespace lsr::detail
