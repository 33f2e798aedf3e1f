// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_resolution_sample.cpp
#include "fit/mesh_resolution_sample.h"

#include <cmath>
#include <cstdint>

namespace lsr {
namespace {

// A uniform number in [0, 1) from the index (splitmix64's finaliser).
double uniform(std::uint64_t i) {
  std::uint64_t z = i + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53;
}

}  // namespace

template <int D>
std::vector<Index> mesh_resolution_sample(const std::vector<double>& sampling_scale, const std::vector<double>& scale) {
  std::vector<Index> kept;
  kept.reserve(scale.size());
  for (std::size_t i = 0; i < scale.size(); ++i) {
    if (!(scale[i] > sampling_scale[i]) || uniform(i) < std::pow(sampling_scale[i] / scale[i], D - 1)) kept.push_back(Index(i));
  }
  return kept;
}

template std::vector<Index> mesh_resolution_sample<2>(const std::vector<double>&, const std::vector<double>&);
template std::vector<Index> mesh_resolution_sample<3>(const std::vector<double>&, const std::vector<double>&);

}  // namespace lsr
