// SPDX-License-Identifier: BSD-3-Clause
/// @file compare_methods.h
/// @brief The reconstructors lsrecon-compare runs on a case: lsrecon (the PCL class), and PCL's
/// Poisson (with estimated, lsrecon's or the true normals), marching cubes (Hoppe, RBF) and
/// greedy projection, normal estimation included where a method needs normals; lsrecon-tiles is
/// lsrecon with its front in tiles (--solve-tiles, at least 2).
#pragma once

#include "compare_cases.h"

#include <pcl/PolygonMesh.h>

#include <string>
#include <vector>

namespace lsr::demos {

/// @brief The method names, in the order of the tables.
extern const std::vector<std::string> kMethods;

/// @brief What lsrecon-compare passes on to lsrecon.
struct LsreconOptions {
  double hole_radius = -1.0;    ///< lsrecon's hole_radius (negative: automatic)
  double max_resolution = 0.0;  ///< lsrecon's max_resolution (0: its default)
  int solve_tiles = 1;          ///< lsrecon's solve_tiles (1: one mesh)
};

struct Produced {
  pcl::PolygonMesh mesh;
  std::string note;
  std::vector<double> residuals;  // lsrecon only
  bool indexed = false;           // lsrecon's: its triangles share their vertices (PCL's are welded)
};

/// @brief Runs `method` on the case's points.
/// @throw lsr::InvalidInput for an unknown method.
Produced run_method(const std::string& method, const CompareCase& c, const LsreconOptions& s);

}  // namespace lsr::demos
