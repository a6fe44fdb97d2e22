// Whole-step MPM throughput (Google Benchmark): one uncoupled MpmSolver::advance() (USL, FLIP,
// linear elastic) per iteration, for each shape function in 2D and 3D, on one core. The counter
// particle_steps is particles x steps per second of CPU time (kIsRate; CPU time, not wall time,
// because the machines are shared). Each case also runs with the health check every program's loop
// calls after each step (".../health_check"): the difference is its cost. FusedReference/<dim>/<shape>
// is the minimal fused kernel (fused_reference.h) on the same block, the reference figure.
//
// Sample run (the figures of docs/mpm.md, Performance):
//   build-mpm/benchmarks/mpm/bench_mpm_step --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Problems: 2D, a 256 x 256-cell elastic block (2 x 2 particles per cell: 262,144 particles) in a
// 264 x 264 mesh; 3D, a 24^3-cell block (2 x 2 x 2 per cell: 110,592 particles) in a 30^3 mesh.
// Walls all round. The block starts with a smooth shear-and-compression velocity field, so
// stresses and the velocity gradient are non-trivial and particles cross cells.
#include <benchmark/benchmark.h>
#include <mpi.h>

#include <cmath>
#include <numbers>
#include <string>

#include "fused_reference.h"
#include "mpm/solver/health_check.h"
#include "mpm_problems.h"

using namespace mpmice;
namespace pr = mpmice::mpm::problems;

namespace {

core::Scene blockScene(int dim, const std::string& shape) {
  const int block = dim == 2 ? 256 : 24, margin = dim == 2 ? 4 : 3;
  const int n = block + 2 * margin;
  const double h = 1.0 / block;
  core::Scene s;
  s.name = "bench_block";
  s.mesh = core::Mesh(dim, {0, 0, 0}, {h, h, dim == 3 ? h : 1.0}, {n, n, dim == 3 ? n : 1});
  for (auto& f : s.boundary) f.type = core::BoundaryType::NoSlipWall;
  s.time.cfl = 0.4;
  s.time.end = 1e300;
  s.materials = {pr::solid("block", 1000, pr::elastic("linear_elastic", 1e6, 0.3))};
  core::ShapeSpec box;
  box.type = "box";
  const double lo = margin * h, hi = (margin + block) * h;
  box.lo = {lo, lo, dim == 3 ? lo : 0};
  box.hi = {hi, hi, dim == 3 ? hi : 0};
  s.geometry = {pr::region("block", box, "block", {2, 2, dim == 3 ? 2 : 1})};
  s.mpm.shape_function = shape;
  s.mpm.update = "usl";
  s.mpm.flip = 1.0;
  return s;
}

void initVelocity(mpm::MpmSolver& solver, int dim) {
  auto& p = solver.particles();
  const double k = 2 * std::numbers::pi;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < dim; ++d) {
      const double x = p.x[d][i], y = p.x[(d + 1) % dim][i];
      p.v[d][i] = 0.05 * std::sin(k * x) + 0.03 * std::cos(k * y);
    }
}

// health: 0 the step, 1 the step and the health check, 2 the health check alone.
void BM_MpmStep(benchmark::State& state, int dim, const std::string& shape, int health) {
  mpm::MpmSolver solver(blockScene(dim, shape), core::Comm(MPI_COMM_SELF));
  initVelocity(solver, dim);
  for (int k = 0; k < 2; ++k) solver.advance();  // warm-up: first touch of every field
  const auto np = static_cast<double>(solver.globalParticleCount());
  if (health == 2) {
    for (auto _ : state) mpm::checkHealth(solver);
    return;
  }
  for (auto _ : state) {
    solver.advance();
    if (health == 1) mpm::checkHealth(solver);  // what every program's loop adds per step
    benchmark::ClobberMemory();
  }
  state.counters["particle_steps"] =
      benchmark::Counter(np * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["particles"] = np;
}

// The minimal fused kernel (fused_reference.h) on the same block, same particles and material.
template <class Shape, int Dim>
void BM_FusedReference(benchmark::State& state) {
  const int block = Dim == 2 ? 256 : 24, margin = Dim == 2 ? 4 : 3;
  mpm::bench::FusedReference<Shape, Dim> ref(block, margin, 1000, 1e6, 0.3, 0.4);
  for (int k = 0; k < 2; ++k) ref.step();  // warm-up, as the solver's case
  for (auto _ : state) {
    ref.step();
    benchmark::ClobberMemory();
  }
  const auto np = static_cast<double>(ref.size());
  state.counters["particle_steps"] =
      benchmark::Counter(np * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["particles"] = np;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  for (int dim : {2, 3})
    for (const char* shape : {"linear", "gimp", "bspline2", "bspline3"})
      for (const int health : {0, 1})
        benchmark::RegisterBenchmark(
            ("MpmStep/" + std::to_string(dim) + "D/" + shape + (health ? "/health_check" : "")).c_str(),
            [dim, s = std::string(shape), health](benchmark::State& st) { BM_MpmStep(st, dim, s, health); })
            ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("FusedReference/2D/linear", BM_FusedReference<mpm::LinearShape, 2>)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("FusedReference/2D/bspline2", BM_FusedReference<mpm::BSpline2Shape, 2>)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("FusedReference/3D/linear", BM_FusedReference<mpm::LinearShape, 3>)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("FusedReference/3D/bspline2", BM_FusedReference<mpm::BSpline2Shape, 3>)
      ->Unit(benchmark::kMillisecond);
  for (int dim : {2, 3})
    benchmark::RegisterBenchmark(("MpmHealthCheckAlone/" + std::to_string(dim) + "D").c_str(),
                                 [dim](benchmark::State& st) { BM_MpmStep(st, dim, "linear", 2); })
        ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  MPI_Finalize();
  return 0;
}
