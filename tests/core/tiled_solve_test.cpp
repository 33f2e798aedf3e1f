// SPDX-License-Identifier: BSD-3-Clause
/// @file tiled_solve_test.cpp
/// @brief The tiles of the solve (tiles/tiled_solve.h): their cores partition the box, and every
/// seam vertex a tile's kept simplices read from a neighbour was given by its owner, which
/// holds only where the tiles' meshes agree vertex for vertex across the seams; workers that
/// share the tiles give worker 0 what one process welds.
#include "tiles/tiled_solve.h"

#include "lsrecon/testdata/analytic_shapes.h"
#include "sampling/sampled_data.h"
#include "thread_exchange.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <thread>
#include <vector>

namespace lsr::detail {
namespace {

TEST(TiledSolve, CoresPartitionTheBoxAndLieInTheirRegions) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k : {2, 3}) {
    for (int n = 0; n < 2000; ++n) {
      const Vec<3> x(unit(random), unit(random), unit(random));
      int owners = 0;
      for (int t = 0; t < k * k * k; ++t) {
        const TileBox<3> b = tile_box<3>(t, k, 0.1);
        const bool in_core = ((x - b.lo).array() >= 0.0).all() && ((b.hi - x).array() > 0.0).all();
        owners += in_core;
        if (in_core) {
          EXPECT_TRUE(((x - b.region_lo).array() >= 0.0).all() && ((b.region_hi - x).array() >= 0.0).all());
        }
      }
      EXPECT_EQ(owners, 1);
    }
  }
}

// A circle's sample, to be solved in 3 x 3 tiles: cut planes off the mesh's dyadic lines (3D,
// through the reconstruction: tiled_reconstruction_test.cpp).
struct CircleInNineTiles {
  ReconstructionOptions o = nine_tiles();
  ReconstructionResult<2> r;
  StageClock clock{r.seconds, r.stages};
  SampledData<2> sampled = sampled_data<2>(Circle{Vec<2>(0, 0), 1.0}.sample(3000), o, HeightFieldsAt::none, Progress(), r, clock);
  static ReconstructionOptions nine_tiles() {
    ReconstructionOptions nine;
    nine.limits.solve_tiles = 3;
    return nine;
  }
};

TEST(TiledSolve, EverySeamVertexIsGivenByItsOwnerAndTheCircleIsClosed) {
  CircleInNineTiles c;
  const TiledFront<2> f = solve_in_tiles<2>(c.sampled, c.o, 0.0, 20'000'000, nullptr, c.r, Progress(), c.clock);
  EXPECT_EQ(f.seam_mismatches, 0);
  // Closed: every point ends two segments, one as its first point and one as its second.
  std::vector<int> first(f.surface.vertices.size(), 0), second(f.surface.vertices.size(), 0);
  for (const auto& e : f.surface.facets) ++first[std::size_t(e[0])], ++second[std::size_t(e[1])];
  for (std::size_t v = 0; v < first.size(); ++v) ASSERT_TRUE(first[v] == 1 && second[v] == 1) << "point " << v;
  EXPECT_EQ(closed_loops(f.surface).size(), 1u);
}

// Three workers (threads) share the 9 tiles of a circle, unevenly (4, 3 and 2 tiles): worker 0
// gets them in tile order and welds the same bytes as one process, with the same loop fields.
TEST(TiledSolve, WorkersSolveTheirTilesAndWorkerZeroWeldsWhatOneProcessWelds) {
  CircleInNineTiles c;
  const ReconstructionOptions& o = c.o;
  const SampledData<2>& sampled = c.sampled;
  const ReconstructionResult<2>& one_r = c.r;
  const TiledFront<2> one = solve_in_tiles<2>(sampled, o, 0.0, 20'000'000, nullptr, c.r, Progress(), c.clock);
  ThreadExchange::Meeting meeting(3);
  std::vector<TiledFront<2>> fronts(3);
  std::vector<ReconstructionResult<2>> results(3);
  std::vector<std::thread> threads;
  for (int w = 0; w < 3; ++w) {
    threads.emplace_back([&, w] {
      ReconstructionOptions ow = o;
      ow.limits.exchange = std::make_shared<const ThreadExchange>(w, meeting);
      ow.limits.threads = 1;
      StageClock own(results[std::size_t(w)].seconds, results[std::size_t(w)].stages);
      fronts[std::size_t(w)] = solve_in_tiles<2>(sampled, ow, 0.0, 20'000'000, nullptr, results[std::size_t(w)], Progress(), own);
    });
  }
  for (auto& t : threads) t.join();
  const TiledFront<2>& zero = fronts[0];
  ASSERT_EQ(zero.surface.vertices.size(), one.surface.vertices.size());
  EXPECT_EQ(std::memcmp(static_cast<const void*>(zero.surface.vertices.data()), static_cast<const void*>(one.surface.vertices.data()),
                        one.surface.vertices.size() * sizeof(Vec<2>)),
            0);
  EXPECT_EQ(zero.surface.facets, one.surface.facets);
  EXPECT_EQ(std::memcmp(static_cast<const void*>(zero.normals.data()), static_cast<const void*>(one.normals.data()), one.normals.size() * sizeof(Vec<2>)),
            0);
  EXPECT_EQ(zero.level, one.level);
  EXPECT_EQ(results[0].iterations, one_r.iterations);
  EXPECT_EQ(results[0].mesh_vertices, one_r.mesh_vertices);
  EXPECT_EQ(results[0].residual, one_r.residual);
  for (int w : {1, 2}) {
    EXPECT_EQ(results[std::size_t(w)].status, ReconstructionStatus::shared);
    EXPECT_TRUE(fronts[std::size_t(w)].surface.vertices.empty());
  }
}

}  // namespace
}  // namespace lsr::detail
