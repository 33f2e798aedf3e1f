// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_mpi_test.cpp
/// @brief lsrecon-mpi under mpirun -np 2 on one machine: the ranks split the cloud and share the
/// sampling (and the front's tiles), and rank 0 writes what lsrecon --tiles 2 writes in one
/// process, byte for byte; a rank that fails stops them all and nothing is written.
#include "cli_fixture.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/testdata/simulated_scan.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace {

using lsr_test::Cli;
using lsr_test::CliRun;
using lsr_test::expect_closed_mesh;

// Open MPI refuses root unless told; --bind-to none leaves each rank's OpenMP threads free.
// Open MPI never frees what MPI_Init allocates in its plugins (LeakSanitizer counts 3,000
// blocks), so leaks are not looked for here: lsrecon runs the same code without MPI, and they
// are looked for there.
const std::string kMpiRun = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ASAN_OPTIONS=detect_leaks=0 " LSRECON_MPIEXEC
                            " -np 2 --oversubscribe --bind-to none " LSRECON_MPI_CLI;

// A line scan from above of the double torus: scan lines (their wide neighbourhoods and empty
// discs), an unseen underside (rims), genus 2, with isolated points (dropped, then the sampling
// again) and copies at the end of the file (their first copies in the other rank's share).
// Each rank reads half the file, the ranks sort the cloud between them and each estimates its
// run with a halo; rank 0 gets the sample. At --max-resolution 48 the sample is thinned (each
// run's, with a halo of its own). With --solve-tiles 2 every rank gets the sample, solves every
// other of the front's 8 tiles and sends rank 0 what it welds (tiles/tile_outputs.h).
TEST_F(Cli, MpiRanksShareTheTilesAndRankZeroWritesWhatOneProcessWrites) {
  lsr::ScannerSettings scanner;
  scanner.from_above = true;
  scanner.lines = 40;
  scanner.samples_per_line = 400;
  lsr::Points<3> cloud = lsr::simulate_scan(lsr::make_test_shape("double-torus"), scanner).points;
  for (int k = 0; k < 4; ++k) cloud.emplace_back(-1.0 + 0.5 * k, 1.5, 0.9);
  for (std::size_t i = 0; i < 300; i += 3) cloud.push_back(cloud[i]);
  lsr::adapters::write_points(path("scan.ply"), cloud);

  for (const std::string options : {"", " --max-resolution 48", " --solve-tiles 2"}) {
    const CliRun one = run(path("scan.ply") + " " + path("one.ply") + " --tiles 2 --report " + path("one.json") + options);
    ASSERT_EQ(one.status, 0) << one.output;
    const CliRun two = run_program(kMpiRun, path("scan.ply") + " " + path("two.ply") + " --report " + path("two.json") + options);
    ASSERT_EQ(two.status, 0) << two.output;
    const bool tiled = options == " --solve-tiles 2";
    EXPECT_NE(two.output.find(std::string("rank 1 of 2 shared its run of the cloud") + (tiled ? " and solved its tiles" : "") + ", peak memory"),
              std::string::npos)
        << two.output;
    EXPECT_EQ(read("one.ply"), read("two.ply")) << options;
    expect_closed_mesh(path("two.ply"), 2);
    const nlohmann::json a = nlohmann::json::parse(read("one.json")), b = nlohmann::json::parse(read("two.json"));
    for (const char* key : {"time_steps", "spacing_input_units", "noise_input_units", "input_points", "outlier_points", "duplicate_points"}) {
      EXPECT_EQ(a[key], b[key]) << key << options;
    }
    EXPECT_GT(b["outlier_points"].get<int>(), 0);
    EXPECT_EQ(b["duplicate_points"].get<int>(), 100);
  }
}

TEST_F(Cli, AFailingMpiRankStopsThemAllAndNothingIsWritten) {
  const CliRun r = run_program(kMpiRun, path("missing.ply") + " " + path("out.ply"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("missing.ply"), std::string::npos) << r.output;
  EXPECT_FALSE(std::ifstream(path("out.ply")).good());
  // What needs the whole cloud in one process is refused by every rank.
  lsr::Points<3> circle;
  for (int i = 0; i < 200; ++i) circle.emplace_back(std::cos(0.0314 * i), std::sin(0.0314 * i), 0.0);
  lsr::adapters::write_points(path("circle.ply"), circle);
  const CliRun planar = run_program(kMpiRun, path("circle.ply") + " " + path("out.svg"));
  EXPECT_NE(planar.status, 0);
  EXPECT_NE(planar.output.find("lsrecon-mpi reconstructs surfaces"), std::string::npos) << planar.output;
  const CliRun outliers = run_program(kMpiRun, path("circle.ply") + " " + path("out.ply") + " --sor-mean-k 8");
  EXPECT_NE(outliers.status, 0);
  EXPECT_NE(outliers.output.find("reads the whole cloud"), std::string::npos) << outliers.output;
  EXPECT_FALSE(std::ifstream(path("out.svg")).good());
  EXPECT_FALSE(std::ifstream(path("out.ply")).good());
}

}  // namespace
