// The adiabatic piston through the coupling (configs/piston.yaml, Uintah's pistonVal problem): a
// free copper piston moving at v into trapped air, the gas started in the quasi-static state.
// Exact: the quasi-static answer with the piston's own dynamics (it is free, so it decelerates),
//   s' = v,  M v' = -(p - p_L),  p = p0 (h0 / (h0 - s))^gamma,  p_L = p0 (hL0 / (hL0 + s))^gamma,
// integrated by RK4 to round-off (src/study/reference/piston.h, the study's `piston` reference). Asserted at the scene's spacing: the piston's displacement, and
// the mean pressure of the trapped gas (its pure-gas cells) against p(t) every millisecond.
// The goal is 1 % (issue 12); the bounds are the ones set before the scenes moved the piston's
// volume with MPM's face transport (coupling.solid_transport: mpm): 4.3 % then (ICE's face
// fluxes: the gas advected across the moving piston's surface cells), 2.9 % now
// (docs/verification-coupled.md, "The piston").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "coupled_run.h"
#include "study/reference/piston.h"
#include "serial_mpi.h"

namespace mpmice::test {
namespace {

using study::PistonExact;
using study::PistonSetup;

// Bounds (docs/verification-coupled.md): at the scene's spacing p(t) within 5 % (measured 2.90 %;
// 4.3 % with solid_transport ice), the final pressure within 4 % (2.16 %; 3.4 %); at 50 and 100
// cells (to 5 ms) p(t) within 10 % (0.38 % and 0.08 %; 1.0 % and 1.8 %).
constexpr double kWorstBound = 0.05, kFinalBound = 0.04, kWorstBoundAnyResolution = 0.10;

/// One run: the largest and the final |p / p_exact - 1| of the trapped gas (every millisecond) and
/// the largest relative displacement error.
struct PistonErrors {
  double worst = 0, final = 0, displacement = 0;
};

PistonErrors runPiston(const char* path, double cfl = 0) {
  core::Scene scene = core::loadScene(path);
  if (cfl > 0) scene.time.cfl = cfl;
  CoupledRun run(std::move(scene));
  const core::Scene& sc = run.scene;
  const PistonSetup e = study::pistonSetup(sc);
  const auto& parts = run.mpm.particles();
  const auto& gas = run.ice.state().mat[static_cast<std::size_t>(sc.materialIndex("air"))];
  const auto displacement = [&] {
    double sum = 0, m = 0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      sum += parts.mass[i] * (parts.x[0][i] - parts.x0[0][i]);
      m += parts.mass[i];
    }
    return sum / m;
  };
  // Mean pressure of the pure-gas cells ahead of the piston.
  const auto trappedPressure = [&](double s) {
    double sum = 0;
    int n = 0;
    const core::Box& b = run.ice.ownedBox();
    for (int i = b.lo[0]; i <= b.hi[0]; ++i)
      if (sc.mesh.cellCenter(0, i) > e.xHi + s && gas.theta(i, 0, 0) > 0.999) {
        sum += run.ice.pressure()(i, 0, 0);
        ++n;
      }
    EXPECT_GT(n, 0);
    return sum / n;
  };
  PistonErrors out;
  const double every = 1e-3;
  std::printf("%s (%d cells)\n", path, sc.mesh.cells()[0]);
  for (double t = every; t <= sc.time.end * (1 + 1e-12); t += every) {
    run.runTo(std::min(t, sc.time.end));
    const PistonExact ex = study::pistonExact(e, run.time());
    const double s = displacement();
    const double p = trappedPressure(s);
    const double err = p / ex.p - 1;
    out.worst = std::max(out.worst, std::abs(err));
    out.final = std::abs(err);
    out.displacement = std::max(out.displacement, std::abs(s / ex.s - 1));
    std::printf("t %.4f: displacement %.5f (exact %.5f), p %.6g (exact %.6g, error %+.4f)\n", run.time(), s, ex.s, p,
                ex.p, err);
  }
  std::printf("largest |p / p_exact - 1| = %.4f, final %.4f, displacement %.4f\n", out.worst, out.final,
              out.displacement);
  return out;
}

TEST(AdiabaticPiston, PressureFollowsTheAdiabatAtTheScenesSpacing) {
  const PistonErrors r = runPiston(PISTON_SCENE);
  EXPECT_LT(r.displacement, 0.01);
  EXPECT_LT(r.worst, kWorstBound) << "p(t) against the adiabat, every millisecond";
  EXPECT_LT(r.final, kFinalBound) << "the final pressure";
}

// The stability map's point CFL 0.7 (docs/stability.md): it used to end with the copper's stored
// stress work at -4.6e8 J and the gas at 14 times the exact pressure (a sawtooth the GIMP / FLIP
// step grows beyond CFL ~0.68 at the copper's free faces; then the MPM health check stopped it at
// step 80). The MPM step now takes at most its stable CFL number (mpm_constants.h, kMaxStableCfl
// 0.5) and the run is the piston again, within the shipped scene's bounds: measured 4.24 % worst, 3.34 %
// final, displacement 0.21 % (the shipped CFL 0.4: 4.31, 3.41, 0.21 %).
TEST(AdiabaticPiston, AtCfl07RunsWithinTheMpmStepsLimit) {
  const PistonErrors r = runPiston(PISTON_SCENE, 0.7);
  EXPECT_LT(r.displacement, 0.01);
  EXPECT_LT(r.worst, kWorstBound) << "p(t) against the adiabat, every millisecond";
  EXPECT_LT(r.final, kFinalBound) << "the final pressure";
}

// The scene at 25 (the shipped one, to 20 ms) and at 50 and 100 cells to 5 ms (2.5 and 5 cells of
// travel: benchmarks/coupled/piston_scene.py N 5e-3, kept short for the suite's time): each run
// completes (before, the trace gas in the copper's cells was pumped to 1e9 K after 0.98 of a cell
// of travel; now its temperature follows the copper's, src/ice/exchange/trace_temperature.cpp),
// the piston's displacement is within 1 % and p(t) within 10 %. With the face transport measured
// 2.90 % (20 ms), 0.38 % and 0.08 % (5 ms); to 20 ms 2.90, 0.90 and 0.25 % (order 1.75). With
// ICE's face fluxes (solid_transport ice) 4.3 % (20 ms), 1.0 % and 1.8 % (5 ms), and no
// convergence (docs/verification-coupled.md). The fitted order is printed, not asserted.
TEST(AdiabaticPiston, ThreeResolutionsComplete) {
  const char* scenes[3] = {PISTON_SCENE, PISTON_SCENE_50, PISTON_SCENE_100};
  double worst[3];
  for (int k = 0; k < 3; ++k) {
    const PistonErrors r = runPiston(scenes[k]);
    worst[k] = r.worst;
    EXPECT_LT(r.displacement, 0.01) << scenes[k];
    EXPECT_LT(r.worst, kWorstBoundAnyResolution) << scenes[k];
  }
  std::printf("largest p(t) errors %.4f %.4f %.4f at 25, 50, 100 cells: fitted order %.2f\n", worst[0], worst[1],
              worst[2], std::log(worst[0] / worst[2]) / std::log(4.0));
}

}  // namespace
}  // namespace mpmice::test
