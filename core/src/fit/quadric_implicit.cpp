// SPDX-License-Identifier: BSD-3-Clause
/// @file quadric_implicit.cpp
#include "fit/quadric_implicit.h"

#include "fit/height_field_fit.h"
#include "sampling/local_sampling.h"
#include "thread_count.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include <omp.h>

namespace lsr {
namespace {

// The PCA neighbourhood's radius in spacings: the k-th neighbour's distance grows like k along
// a curve and like sqrt(k) on a surface.
template <int D>
double straddle_radius() {
  const double ratio = double(LocalSampling<D>::kNeighbours - 1) / LocalSampling<D>::kSpacingRank;
  return D == 2 ? ratio : std::sqrt(ratio);
}

// Rows: an orthonormal tangent basis of n, then n.
template <int D>
Eigen::Matrix<double, D, D> fit_frame(const Vec<D>& n) {
  Eigen::Matrix<double, D, D> f;
  if constexpr (D == 2) {
    f.row(0) = Eigen::RowVector2d(-n.y(), n.x());
  } else {
    const Vec<3> a = std::abs(n.x()) < 0.6 ? Vec<3>::UnitX() : Vec<3>::UnitY();
    const Vec<3> t1 = n.cross(a).normalized();
    f.row(0) = t1.transpose();
    f.row(1) = n.cross(t1).transpose();
  }
  f.row(D - 1) = n.transpose();
  return f;
}

}  // namespace

template <int D>
QuadricImplicit<D>::QuadricImplicit(const NearestPointIndex<D>& data, Points<D> normals,
                                    std::vector<double> spacing, const std::vector<double>& noise, int threads,
                                    const LargeVector<Index>* given, const Progress& progress)
    : data_(&data), spacing_(std::move(spacing)), blend_width2_(spacing_.size()), fits_(data.points().size()) {
  // Read by every blend, twelve times per query: computed once.
  for (std::size_t i = 0; i < spacing_.size(); ++i) blend_width2_[i] = std::pow(std::max(spacing_[i], 1e-12), 2);
  const Points<D>& p = data.points();
  const long n = long(p.size());
  // Neighbourhoods: kFitNeighbours for all, and a second, wider query for the noisy points.
  const int k_clean = std::min<int>(kFitNeighbours, int(p.size()));
  const int k_max = std::min<int>(kMaxFitNeighbours, int(p.size()));
  std::vector<int> size(p.size(), k_clean);
  // 1 - cos of the normal width: the noise widens it as it widens the neighbourhood (normals
  // scattered by noise are not a crease).
  std::vector<double> width(p.size(), 1.0 - std::cos(kNormalWidth));
  for (std::size_t i = 0; i < p.size() && !noise.empty(); ++i) {
    const double ratio = noise[i] / (0.05 * std::max(spacing_[i], 1e-300));
    size[i] = int(std::min<double>(k_max, k_clean * (1.0 + ratio * ratio)));
    width[i] = 1.0 - std::cos(std::min(kPi / 2, kNormalWidth * std::sqrt(1.0 + ratio * ratio)));
  }
  // The wider neighbourhoods in classes of sizes growing by 5/4, each class queried at its
  // largest size: one query for the widest point alone would make every noisy point search as
  // far.
  LargeVector<Index> queried;
  if (!given) data.query_k(p, k_clean, queried, threads);
  const LargeVector<Index>& nearest = given ? *given : queried;
  std::vector<int> class_k;
  for (int k = k_clean; k < k_max;) {
    k = std::min(k_max, k + std::max(1, k / 4));
    class_k.push_back(k);
  }
  const auto class_of = [&](std::size_t i) {
    return size[i] <= k_clean ? -1 : int(std::lower_bound(class_k.begin(), class_k.end(), size[i]) - class_k.begin());
  };
  // Block by block (the points are in Z-order, so a block is a patch): the wide lists of a whole
  // scan would not fit (a 10M-point line scan, most of it noisy: 8.8 GB more at the peak).
  for (long begin = 0; begin < n; begin += kFitBlock) {
    progress.update("fit", double(begin) / double(n));
    const long end = std::min(n, begin + kFitBlock);
    std::vector<Points<D>> members(class_k.size());
    std::vector<LargeVector<Index>> wide(class_k.size());
    std::vector<Index> row(std::size_t(end - begin), -1);
    for (long i = begin; i < end; ++i) {
      const int c = class_of(std::size_t(i));
      if (c < 0) continue;
      row[std::size_t(i - begin)] = Index(members[std::size_t(c)].size());
      members[std::size_t(c)].push_back(p[std::size_t(i)]);
    }
    for (std::size_t c = 0; c < class_k.size(); ++c) {
      if (!members[c].empty()) data.query_k(members[c], class_k[c], wide[c], threads);
    }
#pragma omp parallel for schedule(static) num_threads(detail::thread_count(threads))
    for (long i = begin; i < end; ++i) {
      const int c = class_of(std::size_t(i));
      const Index* near = c >= 0 ? &wide[std::size_t(c)][std::size_t(row[std::size_t(i - begin)]) * std::size_t(class_k[std::size_t(c)])]
                                 : &nearest[std::size_t(i) * k_clean];
      const int k = size[std::size_t(i)];
      const double sigma = noise.empty() ? 0.0 : noise[std::size_t(i)];
      Fit f = fit_point(p, normals, std::size_t(i), near, k, width[std::size_t(i)], sigma);
      if (c >= 0) {
        // Widened, it must still pass its own nearest within the noise (kMaxMissRatio).
        const Index* own = &nearest[std::size_t(i) * k_clean];
        double miss = 0.0;
        for (int j = 0; j < k_clean; ++j) {
          miss += std::pow(fit_value(f, p[std::size_t(i)], p[std::size_t(own[j])], nullptr), 2);
        }
        if (miss > kMaxMissRatio * k_clean * sigma * sigma) {
          f = fit_point(p, normals, std::size_t(i), near, k_clean, width[std::size_t(i)], sigma);
        }
      }
      fits_[std::size_t(i)] = f;
    }
  }
  progress.update("fit", 1.0);
}

template <int D>
auto QuadricImplicit<D>::fit_point(const Points<D>& p, const Points<D>& normals, std::size_t i, const Index* near, int k,
                                   double width, double noise) const -> Fit {
  Fit f;
  f.normal = normals[i];
  const Eigen::Matrix<double, D, D> frame = fit_frame<D>(f.normal);
  double reach = 0.0;
  for (int j = 0; j < k; ++j) reach = std::max(reach, (p[near[j]] - p[i]).norm());
  f.reach = std::max(reach, 1e-12);
  f.fade_width2 = std::pow(2.0 * f.reach, 2);
  const double r2 = std::pow(1.2 * f.reach, 2);
  // Where the other side of a thin part lies among the PCA neighbours, the normals straddle
  // both sides and tell no crease: plain weights there (the normals' weights open handles in
  // thin parts).
  double inverse_width = 1.0 / width;
  const double straddle = straddle_radius<D>() * spacing_[i];
  for (int j = 0; j < k; ++j) {
    if (normals[near[j]].dot(normals[i]) <= 0.0 && (p[near[j]] - p[i]).norm() < straddle) {
      inverse_width = 0.0;
    }
  }
  const auto fit = [&](auto& equations) {
    constexpr int P = std::decay_t<decltype(equations.atz)>::RowsAtCompileTime;
    for (int j = 0; j < k; ++j) {
      const double cosine = normals[near[j]].dot(normals[i]);
      if (cosine <= 0.0) continue;  // the other side of a thin part
      const Vec<D> local = frame * (p[near[j]] - p[i]);
      const double w = std::pow(1.0 - local.squaredNorm() / r2, 2) * std::exp(-(1.0 - cosine) * inverse_width);
      equations.add(w, height_monomials<D, P>(local.template head<D - 1>()), local[D - 1]);
    }
    equations.regularize(f.reach);
  };
  Eigen::Matrix<double, kQuadricTerms<D>, 1> x;
  bool fitted = false;
  if constexpr (D == 3) {
    if (k >= kCubicNeighbours) {
      HeightFieldEquations<D, kCubicTerms> e;
      fit(e);
      // Where the neighbours lie to one side (a hole's rim, a scan's border), the cubic terms
      // are not held on the other, over which they extrapolate (bumps over holes).
      // The weighted centroid (sum w t / sum w, ata's first row) tells it.
      const double offset = std::hypot(e.ata(0, 1), e.ata(0, 2)) / e.ata(0, 0);
      if (offset < kCubicBalance * f.reach) {
        const CubicSelection selected = select_cubic(e, noise);
        x = selected.quadric;
        f.cubic = selected.cubic;
        fitted = true;
      }
    }
  }
  if (!fitted) {
    HeightFieldEquations<D, kQuadricTerms<D>> e;
    fit(e);
    x = e.solve();
  }
  f.c0 = x[0];
  f.g = x.template segment<D - 1>(1);
  if constexpr (D == 2) {
    f.h(0, 0) = x[2];
  } else {
    f.h << x[3], x[4], x[4], x[5];
  }
  return f;
}

template <int D>
double QuadricImplicit<D>::fit_value(const Fit& f, const Vec<D>& centre, const Vec<D>& x, Vec<D>* normal) const {
  const Eigen::Matrix<double, D, D> frame = fit_frame<D>(f.normal);
  const Vec<D> local = frame * (x - centre);
  const Eigen::Matrix<double, D - 1, 1> t = local.template head<D - 1>();
  // Far along the tangent the quadric's extrapolation is not trusted: its curvature term fades
  // beyond twice the fitted neighbourhood (sampling holes are spanned by tangent planes).
  const double fade = 1.0 / (1.0 + t.squaredNorm() / f.fade_width2);
  const Eigen::Matrix<double, D - 1, 1> ht = f.h * t;
  double height = f.c0 + f.g.dot(t) + 0.5 * fade * t.dot(ht);
  Eigen::Matrix<double, D - 1, 1> slope = f.g + fade * ht;
  if constexpr (D == 3) {
    // The cubic terms fade faster: their extrapolation grows faster.
    const double a = t[0], b = t[1], w = fade * fade;
    const auto& c = f.cubic;
    height += w * (c[0] * a * a * a / 6.0 + 0.5 * c[1] * a * a * b + 0.5 * c[2] * a * b * b + c[3] * b * b * b / 6.0);
    slope[0] += w * (0.5 * c[0] * a * a + c[1] * a * b + 0.5 * c[2] * b * b);
    slope[1] += w * (0.5 * c[1] * a * a + c[2] * a * b + 0.5 * c[3] * b * b);
  }
  const double norm = std::sqrt(1.0 + slope.squaredNorm());
  if (normal) {
    Vec<D> n_local;
    n_local.template head<D - 1>() = -slope;
    n_local[D - 1] = 1.0;
    *normal = frame.transpose() * n_local / norm;
  }
  return (local[D - 1] - height) / norm;
}

template <int D>
void QuadricImplicit<D>::evaluate(const Points<D>& queries, std::vector<double>& value, Points<D>* normal,
                                  int threads) const {
  const int k = std::min<int>(kBlendCentres, int(data_->points().size()));
  LargeVector<Index> nearest;
  data_->query_k(queries, k, nearest, threads);
  blend(queries, nearest, k, value, normal, threads);
}

template <int D>
void QuadricImplicit<D>::blend(const Points<D>& queries, const LargeVector<Index>& nearest, int k,
                               std::vector<double>& value, Points<D>* normal, int threads) const {
  const Points<D>& p = data_->points();
  value.assign(queries.size(), 0.0);
  if (normal) normal->assign(queries.size(), Vec<D>::Zero());
  const long n = long(queries.size());
#pragma omp parallel for schedule(static) num_threads(detail::thread_count(threads))
  for (long q = 0; q < n; ++q) {
    const Index* near = &nearest[std::size_t(q) * k];
    // Gaussian weights of width spacing_i, relative to the largest so that far queries do not
    // underflow to 0 / 0.
    double exponent[32];
    double top = -std::numeric_limits<double>::infinity();
    for (int j = 0; j < k; ++j) {
      exponent[j] = -(queries[q] - p[near[j]]).squaredNorm() / blend_width2_[near[j]];
      top = std::max(top, exponent[j]);
    }
    double sum = 0.0, weights = 0.0;
    Vec<D> nsum = Vec<D>::Zero();
    for (int j = 0; j < k; ++j) {
      const double w = std::exp(exponent[j] - top);
      Vec<D> nj;
      sum += w * fit_value(fits_[near[j]], p[near[j]], queries[q], normal ? &nj : nullptr);
      if (normal) nsum += w * nj;
      weights += w;
    }
    value[q] = sum / weights;
    if (normal) (*normal)[q] = nsum.normalized();
  }
}

template <int D>
Points<D> QuadricImplicit<D>::project(Points<D>& points, int threads) const {
  const int k = std::min<int>(kBlendCentres, int(data_->points().size()));
  LargeVector<Index> nearest;
  data_->query_k(points, k, nearest, threads);
  std::vector<double> f;
  Points<D> n;
  for (int step = 0; step < 2; ++step) {
    blend(points, nearest, k, f, &n, threads);
    for (std::size_t i = 0; i < points.size(); ++i) points[i] -= f[i] * n[i];
  }
  return n;
}

template class QuadricImplicit<2>;
template class QuadricImplicit<3>;

}  // namespace lsr
