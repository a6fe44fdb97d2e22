// ICE throughput on one core: cell-steps per second for 1, 2 and 3 materials.
//   bench_ice                      (MPI is initialised here; run as a plain program)
// Cases: the 1D Sod tube on 10,000 cells (1 material, the rhoCentralFoam comparison's size), and
// a 2D 128 x 128 periodic box with a pressure bump where every cell holds 1, 2 or 3 materials
// (ideal gas, a second ideal gas, stiffened-gas water), explicit pressure, second-order advection.
// The second argument 1: with the health check every program's loop adds per step (its cost).
#include <benchmark/benchmark.h>
#include <mpi.h>

#include "ice/solver/health_check.h"
#include "ice_test_scenes.h"

using namespace mpmice;

namespace {

core::Scene mixtureBox(int nm, int n) {
  core::Scene s;
  s.name = "bench";
  s.mesh = core::Mesh(2, {0, 0, 0}, {1.0 / n, 1.0 / n, 1}, {n, n, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.time.end = 1e30;
  s.materials = {test::idealGas("air"), test::idealGas("helium", 1.67, 3116), test::stiffenedGas("water", 4.4, 6e8)};
  s.materials.resize(static_cast<std::size_t>(nm));
  std::vector<core::FillSpec> fill;
  for (int r = 0; r < nm; ++r) fill.push_back({s.materials[r].name, 1.0 / nm});
  core::ShapeSpec ball;
  ball.type = "sphere";
  ball.center = {0.5, 0.5, 0};
  ball.radius = 0.2;
  s.geometry = {test::region("all", test::box({0, 0, 0}, {1, 1, 1}), fill, 1e5, 0, {10, 5, 0}),
                test::region("bump", ball, fill, 2e5, 0, {10, 5, 0})};
  for (auto& g : s.geometry) g.density.reset();
  return s;
}

void BM_Sod1D(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const core::Scene sc = test::shockTube(n, {1, 0, 1}, {0.125, 0, 0.1}, 0.5, 1e30);
  ice::IceSolver s(sc, core::Comm(MPI_COMM_SELF));
  const bool health = st.range(1) != 0;  // with the health check every program's loop adds per step
  for (int i = 0; i < 20; ++i) s.step();
  for (auto _ : st) {
    s.step();
    if (health) ice::checkHealth(s);
  }
  st.counters["cell_steps_per_s"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Box2D(benchmark::State& st) {
  const int nm = static_cast<int>(st.range(0));
  const int n = 128;
  ice::IceSolver s(mixtureBox(nm, n), core::Comm(MPI_COMM_SELF));
  const bool health = st.range(1) != 0;
  for (int i = 0; i < 5; ++i) s.step();
  for (auto _ : st) {
    s.step();
    if (health) ice::checkHealth(s);
  }
  st.counters["cell_steps_per_s"] = benchmark::Counter(double(n * n), benchmark::Counter::kIsIterationInvariantRate);
  st.counters["materials"] = nm;
}

// The health check alone, on the 2D box after 5 steps (its cost against BM_Box2D's step).
void BM_HealthCheck2D(benchmark::State& st) {
  const int nm = static_cast<int>(st.range(0));
  ice::IceSolver s(mixtureBox(nm, 128), core::Comm(MPI_COMM_SELF));
  for (int i = 0; i < 5; ++i) s.step();
  for (auto _ : st) ice::checkHealth(s);
  st.counters["materials"] = nm;
}

}  // namespace

BENCHMARK(BM_HealthCheck2D)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sod1D)->Args({10000, 0})->Args({10000, 1})->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(BM_Box2D)
    ->Args({1, 0})
    ->Args({1, 1})
    ->Args({2, 0})
    ->Args({2, 1})
    ->Args({3, 0})
    ->Args({3, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  MPI_Finalize();
  return 0;
}
