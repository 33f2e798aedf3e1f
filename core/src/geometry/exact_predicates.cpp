// SPDX-License-Identifier: BSD-3-Clause
/// @file exact_predicates.cpp
/// @brief The exact paths: every double is an integer times a power of two; brought to the
/// smallest exponent among a predicate's inputs, they are integers, and the sign of a
/// homogeneous polynomial of them is the sign of the same polynomial of the doubles.
#include "geometry/exact_predicates.h"

#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>

namespace lsr::detail {
namespace {

using Integer = boost::multiprecision::cpp_int;

// The doubles xs as integers times 2^shift, the same shift for all.
template <std::size_t N>
std::array<Integer, N> as_integers(const std::array<double, N>& xs) {
  std::array<std::int64_t, N> mantissa{};
  std::array<int, N> exponent{};
  int lowest = std::numeric_limits<int>::max();
  for (std::size_t i = 0; i < N; ++i) {
    int e = 0;
    const double fraction = std::frexp(xs[i], &e);  // xs[i] = fraction 2^e, |fraction| in [0.5, 1)
    mantissa[i] = std::int64_t(std::ldexp(fraction, 53));
    exponent[i] = e - 53;
    if (mantissa[i] != 0) lowest = std::min(lowest, exponent[i]);
  }
  std::array<Integer, N> out;
  for (std::size_t i = 0; i < N; ++i) {
    out[i] = mantissa[i];
    if (mantissa[i] != 0) out[i] <<= unsigned(exponent[i] - lowest);
  }
  return out;
}

int sign_of(const Integer& x) { return x.sign(); }

}  // namespace

int exact_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const auto [iax, iay, ibx, iby, icx, icy] = as_integers<6>({ax, ay, bx, by, cx, cy});
  return sign_of((iax - icx) * (iby - icy) - (iay - icy) * (ibx - icx));
}

int exact_orient3d(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c, const Vec<3>& d) {
  const std::array<Integer, 12> x = as_integers<12>({a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]});
  Integer ad[3], bd[3], cd[3];
  for (std::size_t k = 0; k < 3; ++k) {
    ad[k] = x[k] - x[9 + k];
    bd[k] = x[3 + k] - x[9 + k];
    cd[k] = x[6 + k] - x[9 + k];
  }
  return sign_of(ad[2] * (bd[0] * cd[1] - cd[0] * bd[1]) + bd[2] * (cd[0] * ad[1] - ad[0] * cd[1]) +
                 cd[2] * (ad[0] * bd[1] - bd[0] * ad[1]));
}

template <int D>
int exact_dot_sign(const Vec<D>& a, const Vec<D>& b, const Vec<D>& c) {
  std::array<double, 3 * D> xs{};
  for (int k = 0; k < D; ++k) xs[std::size_t(k)] = a[k], xs[std::size_t(D + k)] = b[k], xs[std::size_t(2 * D + k)] = c[k];
  const auto x = as_integers<3 * D>(xs);
  Integer dot = 0;
  for (std::size_t k = 0; k < std::size_t(D); ++k) dot += (x[D + k] - x[k]) * (x[2 * D + k] - x[k]);
  return sign_of(dot);
}

template int exact_dot_sign<2>(const Vec<2>&, const Vec<2>&, const Vec<2>&);
template int exact_dot_sign<3>(const Vec<3>&, const Vec<3>&, const Vec<3>&);

}  // namespace lsr::detail
