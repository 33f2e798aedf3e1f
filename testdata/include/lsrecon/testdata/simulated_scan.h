// SPDX-License-Identifier: BSD-3-Clause
/// @file simulated_scan.h
/// @brief A line scanner over the test shapes: what real range scans give and i.i.d. samples do
/// not. Rays from several viewpoints in a raster of scan lines (dense along a line, sparse
/// across), range noise that grows with the range, hits lost at grazing angles, surfaces no
/// view sees (from above only: the underside), and a small rigid registration error per view,
/// which leaves overlapping views as sheets a fraction of a spacing apart.
#pragma once

#include "lsrecon/testdata/shape_corpus.h"

#include <cstdint>

namespace lsr {

struct ScannerSettings {
  int views = 6;                  ///< viewpoints, evenly spread (Fibonacci) over the sphere or its upper half
  bool from_above = false;        ///< only viewpoints above the shape's centre (z > 0): the underside unseen
  int lines = 60;                 ///< scan lines per view, across the field of view
  int samples_per_line = 600;     ///< samples along each line
  double distance = 1.5;          ///< viewpoint distance from the shape's centre, in diagonals
  double range_noise = 0.001;     ///< Gaussian range error, relative to the range
  double grazing_cos = 0.1;       ///< hits whose |cos(ray, normal)| is below this are lost; up to twice it, some are
  double registration_angle = 0.002;  ///< per-view rotation error about a random axis through the centre, radians
  double registration_shift = 0.002;  ///< per-view translation error, relative to the diagonal
};

/// @brief The scan of `shape`: hits of each view's raster on the surface (sphere tracing of its
/// signed distance), with their true outward normals at the clean hit, then the view's noise and
/// registration error. Deterministic for a seed, whatever the thread count.
SampledShape simulate_scan(const TestShape& shape, const ScannerSettings& settings, std::uint64_t seed = 1);

}  // namespace lsr
