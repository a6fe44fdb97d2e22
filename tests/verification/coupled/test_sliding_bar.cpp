// A polymer bar sliding along a symmetry plane through a stiff liquid (docs/coupling.md, "A solid
// sliding along a mirror plane"): the filled lattices' bottom strut in small. The bar lies on
// y = 0 (two cells thick, the plane's row nearly all solid), starts at 14 m/s along x and is
// slowed by the liquid it pushes to about 1.3 m/s. With ICE's transport of the solids' cell
// fractions (coupling.solid_transport ice) the donor-cell fractions pump liquid into the plane's
// row as its face velocities oscillate; the trapped liquid's pressure rises there and the energy
// correction of the flux-form work cools that row (277 K after 0.1 ms). With MPM's face transport
// (mpm) the liquid shares only the open part of the faces inside the bar, and the bar keeps its
// temperature: nothing does work on it that heats or cools it beyond the liquid's drag.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "coupled_run.h"
#include "serial_mpi.h"

namespace mpmice::test {
namespace {

const char* kScene = R"(
scene: sliding_bar
mesh: {dim: 2, lower: [0.0, 0.0], upper: [0.006, 0.0015], spacing: [0.00015, 0.00015]}
time: {end: 1.0e-4, cfl: 0.1}
materials:
  - {name: silicone, kind: fluid, specific_heat: 1500.0, viscosity: 100.0, eos: {type: stiffened_gas, gamma: 4.4, p_inf: 1.7045454545e8}}
  - name: polymer
    kind: solid
    density: 1180
    specific_heat: 1500.0
    model: {type: linear_elastic, youngs_modulus: 2.5e9, poissons_ratio: 0.35}
    eos: {type: solid_bulk, threshold_pressure: 5.0e7}
geometry:
  - {name: filler, shape: {type: box, lo: [0.0, 0.0], hi: [0.006, 0.0015]}, material: silicone, density: 970.0, pressure: 5.0e7}
  - {name: bar, shape: {type: box, lo: [0.0006, 0.0], hi: [0.0027, 0.0003]}, material: polymer, velocity: [14.0, 0.0], particles_per_cell: 2, temperature: 300}
boundary:
  x-: {type: outflow, pressure: 5.0e7}
  x+: {type: outflow, pressure: 5.0e7}
  y-: symmetry
  y+: {type: outflow, pressure: 5.0e7}
mpm: {shape_function: bspline2, update: musl}
ice: {advection: first_order, exchange: {momentum: 1.0e15, heat: 0}}
coupling: {schedule: monolithic, solid_transport: mpm}
output: {directory: sliding_bar, interval: 0}
)";

}  // namespace

TEST(SlidingBar, KeepsItsTemperatureAlongAMirrorPlaneWithMpmsFaceTransport) {
  CoupledRun run(core::parseScene(kScene, "sliding_bar (test_sliding_bar.cpp)"));
  double tMin = 1e300, tMax = -1e300;
  run.runTo(run.scene.time.end, [&] {
    const auto& p = run.mpm.particles();
    for (std::size_t i = 0; i < p.size(); ++i) tMin = std::min(tMin, p.temperature[i]), tMax = std::max(tMax, p.temperature[i]);
  });
  const auto& p = run.mpm.particles();
  double u = 0, m = 0;
  for (std::size_t i = 0; i < p.size(); ++i) u += p.mass[i] * p.v[0][i], m += p.mass[i];
  u /= m;
  std::printf("sliding bar, mpm transport: %ld steps, mean velocity at 0.1 ms %.3f m/s, particle temperatures %.3f .. %.3f K\n",
              run.steps, u, tMin, tMax);
  EXPECT_GT(u, 0.5) << "the bar must still be sliding";
  EXPECT_GT(tMin, 299.0);
  EXPECT_LT(tMax, 301.0);
}

}  // namespace mpmice::test
