// SPDX-License-Identifier: BSD-3-Clause
/// @file bench_kernels.cpp
/// @brief Google Benchmark timings of the kernels that dominate a reconstruction (distance
/// queries, refinement, operator application, one time step, renormalisation, extraction) on
/// a sampled sphere, and the whole pipeline at 20k / 200k / 1M points. Prints figures; asserts
/// nothing about speed.
#include "evolution/renormalization.h"
#include "evolution/semi_implicit_step.h"
#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"

#include <benchmark/benchmark.h>

#include <limits>
#include <map>
#include <memory>

namespace {

const lsr::Sphere kSphere{lsr::Vec<3>(0.5, 0.5, 0.5), 0.4};

// One mesh per resolution, shared by the kernels (built once, outside the timings).
struct Fixture {
  explicit Fixture(int resolution) : data(kSphere.sample(100000)) {
    lsr::AdaptiveMeshOptions o;
    o.h_min = 1.0 / resolution;
    mesh = lsr::build_adaptive_mesh(data, o);
    ops = lsr::assemble_p1_operators(mesh.mesh, lsr::compute_simplex_geometry(mesh.mesh));
    std::vector<double> dist;
    data.query(mesh.mesh.vertices, dist);
    d = Eigen::Map<Eigen::VectorXd>(dist.data(), Eigen::Index(dist.size()));
    u.resize(d.size());
    for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = (mesh.mesh.vertices[i] - kSphere.center).norm() - 0.42;
  }
  lsr::NearestPointIndex<3> data;
  lsr::AdaptiveMesh<3> mesh;
  lsr::P1Operators<3> ops;
  Eigen::VectorXd d, u;
};

Fixture& fixture(int resolution) {
  static std::map<int, std::unique_ptr<Fixture>> cache;
  auto& f = cache[resolution];
  if (!f) f = std::make_unique<Fixture>(resolution);
  return *f;
}

void BM_DistanceQueries(benchmark::State& state) {
  const Fixture& f = fixture(int(state.range(0)));
  std::vector<double> dist;
  for (auto _ : state) f.data.query(f.mesh.mesh.vertices, dist);
  state.counters["queries/s"] = benchmark::Counter(double(f.mesh.mesh.vertices.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Refinement(benchmark::State& state) {
  const Fixture& f = fixture(int(state.range(0)));
  lsr::AdaptiveMeshOptions o;
  o.h_min = 1.0 / double(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(lsr::build_adaptive_mesh(f.data, o));
  state.counters["vertices"] = double(f.mesh.mesh.vertices.size());
}

void BM_CurvatureOperatorApply(benchmark::State& state) {
  const Fixture& f = fixture(int(state.range(0)));
  const lsr::SymmetricCurvatureOperator<3> op(f.ops, f.ops.gradient_norms(f.u).cwiseMax(1e-2));
  for (auto _ : state) benchmark::DoNotOptimize(op.apply(f.u));
}

void BM_TimeStep(benchmark::State& state) {
  const Fixture& f = fixture(int(state.range(0)));
  lsr::StepParameters p;
  p.time_step = 0.1;
  p.curvature_weight = 0.3 / double(state.range(0) * state.range(0));
  p.solver_tolerance = 1e-6;
  for (auto _ : state) benchmark::DoNotOptimize(lsr::semi_implicit_step(f.ops, f.d, f.u, p));
}

void BM_Renormalization(benchmark::State& state) {
  const Fixture& f = fixture(int(state.range(0)));
  const lsr::VertexNeighbours g = lsr::vertex_neighbours(f.mesh.mesh);
  for (auto _ : state) {
    Eigen::VectorXd u = f.u;
    lsr::renormalize(f.mesh.mesh, g, u, std::numeric_limits<double>::infinity());
    benchmark::DoNotOptimize(u);
  }
}

void BM_Extraction(benchmark::State& state) {
  const Fixture& f = fixture(int(state.range(0)));
  const std::vector<double> u(f.u.data(), f.u.data() + f.u.size());
  for (auto _ : state) benchmark::DoNotOptimize(lsr::extract_zero_level_set(f.mesh.mesh, u));
}

void BM_Pipeline(benchmark::State& state) {
  const lsr::Points<3> points = lsr::Sphere{lsr::Vec<3>(0, 0, 0), 1.0}.sample(int(state.range(0)));
  lsr::ReconstructionResult<3> r;
  for (auto _ : state) {
    try {
      r = lsr::reconstruct<3>(points);
    } catch (const lsr::MeshTooLarge& e) {
      state.SkipWithError(e.what());  // a refusal is a figure too, not a crash of the benchmark
      return;
    }
  }
  state.counters["mesh_vertices"] = double(r.mesh_vertices);
  state.counters["steps"] = double(r.iterations);
  state.counters["resolution"] = 1.0 / r.h_min;
}

BENCHMARK(BM_DistanceQueries)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Refinement)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_CurvatureOperatorApply)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TimeStep)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_Renormalization)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Extraction)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Pipeline)->Arg(20000)->Arg(200000)->Arg(1000000)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
