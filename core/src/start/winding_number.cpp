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

}  // namespace

template <int D>
double WindingNumber<D>::term(const Vec<D>& dipole, const Vec<D>& at, double radius, const Vec<D>& x) {
  const Vec<D> e = at - x;
  const double r2 = std::max(e.squaredNorm(), radius * radius);
  if (r2 == 0.0) return 0.0;
  if constexpr (D == 3) return dipole.dot(e) / (4.0 * kPi * r2 * std::sqrt(r2));
  return dipole.dot(e) / (2.0 * kPi * r2);
}

template <int D>
double sample_measure(double reach, int others) {
  return (D == 3 ? kPi * reach * reach : 2.0 * reach) / others;
}

template <int D>
WindingNumber<D>::WindingNumber(const Points<D>& points, const Points<D>& normals, const std::vector<double>& areas,
                                const std::vector<double>& radii)
    : order_(points.size()), points_(points), dipoles_(points.size()), radii_(radii) {
  if (radii_.empty()) radii_.assign(points.size(), 0.0);
  for (std::size_t p = 0; p < points.size(); ++p) {
    order_[p] = Index(p);
    dipoles_[p] = areas[p] * normals[p];
  }
  if (points.empty()) return;
  cells_.emplace_back();
  build(0, 0, Index(points.size()), 0);
}

template <int D>
void WindingNumber<D>::build(Index id, Index begin, Index end, int depth) {
  Vec<D> lo = Vec<D>::Constant(HUGE_VAL), hi = Vec<D>::Constant(-HUGE_VAL);
  Vec<D> centroid = Vec<D>::Zero(), dipole = Vec<D>::Zero();
  double reach = 0.0;
  for (Index i = begin; i < end; ++i) {
    const Vec<D>& p = points_[std::size_t(order_[std::size_t(i)])];
    reach = std::max(reach, radii_[std::size_t(order_[std::size_t(i)])]);
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
  cell.reach = reach;
  cell.begin = begin;
  cell.end = end;
  if (end - begin > kLeafPoints && depth < kMaxDepth && radius > 0.0) {
    // Split at the box's middle along each axis: 2^D parts, the empty ones dropped.
    const Vec<D> mid = 0.5 * (lo + hi);
    const auto octant = [&](Index p) {
      const Vec<D>& x = points_[std::size_t(p)];
      int k = 0;
      for (int a = 0; a < D; ++a) k |= int(x[a] > mid[a]) << a;
      return k;
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

template <int D>
double WindingNumber<D>::at(const Vec<D>& x) const {
  double w = 0.0;
  std::vector<Index> stack;
  if (!cells_.empty()) stack.push_back(0);
  while (!stack.empty()) {
    const Cell& c = cells_[std::size_t(stack.back())];
    stack.pop_back();
    const double far = (c.centroid - x).norm();
    if (far > kFarRatio * c.radius && far > c.radius + c.reach) {
      w += term(c.dipole, c.centroid, 0.0, x);
    } else if (c.child < 0) {
      for (Index i = c.begin; i < c.end; ++i) {
        const auto p = std::size_t(order_[std::size_t(i)]);
        w += term(dipoles_[p], points_[p], radii_[p], x);
      }
    } else {
      for (int k = 0; k < c.children; ++k) stack.push_back(c.child + k);
    }
  }
  return w;
}

template class WindingNumber<2>;
template class WindingNumber<3>;
template double sample_measure<2>(double, int);
template double sample_measure<3>(double, int);

}  // namespace lsr::detail
