// SPDX-License-Identifier: BSD-3-Clause
/// @file cli_options.h
/// @brief The lsrecon command line's options: every option once, its default the value
/// lsr::ReconstructionOptions starts with.
#pragma once

#include "lsrecon/adapters/statistical_outliers.h"
#include "lsrecon/core/level_set_reconstruction.h"

#include <string>

namespace lsr::demos {

struct Cli {
  std::string input, output, demo, report, save_points, volume_mesh, init_mesh;
  lsr::ReconstructionOptions solver;
  lsr::adapters::StatisticalOutlierFilter statistical;
  int dim = 0;
  long decimate = 0;
  unsigned smooth = 0;
  int points = 20000;
  int levels = 1;
  bool quiet = false;
};


bool is_2d_shape(const std::string& s);
bool is_curve_output(const std::string& ext);
bool is_mesh_output(const std::string& ext);
const char* initial_front_name(lsr::InitialFront f);
const char* scan_lines_name(lsr::ScanLines s);

/// @brief Parses the command line; exits 2 with a message naming the option on a bad one, 0
/// after --help or --version.
Cli parse(int argc, char** argv);

}  // namespace lsr::demos
