// SPDX-License-Identifier: BSD-3-Clause
/// @file worker_collectives.h
/// @brief Collectives over a TileExchange's all-to-all (lsrecon/core/tile_exchange.h): typed
/// exchanges, gathers, sums and the exact median of values spread over the workers. A null
/// exchange is one worker.
#pragma once

#include "lsrecon/core/tile_exchange.h"

#include <cstring>
#include <vector>

namespace lsr {

inline std::size_t workers_of(const TileExchange* x) { return x ? std::size_t(x->workers()) : 1; }
inline std::size_t worker_of(const TileExchange* x) { return x ? std::size_t(x->worker()) : 0; }

/// @brief Sends out[v] to worker v; returns what each worker sent this one. T is copied as bytes
/// (plain data, or Eigen's fixed-size vectors).
template <class T>
std::vector<std::vector<T>> exchange_values(const TileExchange* x, const std::vector<std::vector<T>>& out) {
  if (!x || x->workers() == 1) return out;
  std::vector<std::vector<unsigned char>> bytes(out.size());
  for (std::size_t v = 0; v < out.size(); ++v) {
    bytes[v].resize(out[v].size() * sizeof(T));
    if (!out[v].empty()) std::memcpy(bytes[v].data(), static_cast<const void*>(out[v].data()), bytes[v].size());
  }
  x->all_to_all(bytes);
  std::vector<std::vector<T>> in(bytes.size());
  for (std::size_t v = 0; v < bytes.size(); ++v) {
    in[v].resize(bytes[v].size() / sizeof(T));
    if (!in[v].empty()) std::memcpy(static_cast<void*>(in[v].data()), bytes[v].data(), in[v].size() * sizeof(T));
    std::vector<unsigned char>().swap(bytes[v]);
  }
  return in;
}

/// @brief Every worker's value, in worker order.
template <class T>
std::vector<T> all_gather(const TileExchange* x, const T& mine) {
  const std::vector<std::vector<T>> in = exchange_values(x, std::vector<std::vector<T>>(workers_of(x), std::vector<T>{mine}));
  std::vector<T> each;
  for (const auto& v : in) each.push_back(v.at(0));
  return each;
}

template <class T>
T sum_over_workers(const TileExchange* x, T mine) {
  T total = T(0);
  for (const T& v : all_gather(x, mine)) total += v;
  return total;
}

/// @brief The value the median() of all workers' values together gives (the element of rank
/// n / 2 among n), exactly: a radix selection on the values' bits, a byte at a time.
double median_over_workers(const TileExchange* x, const double* values, std::size_t n);

}  // namespace lsr
