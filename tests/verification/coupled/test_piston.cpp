// The adiabatic piston through the coupling (configs/piston.yaml, Uintah's pistonVal problem): a
// free copper piston moving at v into trapped air, the gas started in the quasi-static state.
// Exact: the quasi-static answer with the piston's own dynamics (it is free, so it decelerates),
//   s' = v,  M v' = -(p - p_L),  p = p0 (h0 / (h0 - s))^gamma,  p_L = p0 (hL0 / (hL0 + s))^gamma,
// integrated by RK4 to round-off (src/study/reference/piston.h, the study's `piston` reference). Asserted at the scene's spacing: the piston's displacement, and
// the mean pressure of the trapped gas (its pure-gas cells) against p(t) every millisecond.
// The goal is 1 % (issue 12); what the coupling reaches today is asserted (4.2 % measured, the
// bound 5 %): the gas advected across the moving piston's surface cells
// (docs/verification-coupled.md, "The piston").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "coupled_run.h"
#include "study/reference/piston.h"
#include "serial_mpi.h"

namespace mpmice::test {
namespace {

using study::PistonExact;
using study::PistonSetup;

TEST(AdiabaticPiston, PressureFollowsTheAdiabatAtTheScenesSpacing) {
  CoupledRun run(core::loadScene(PISTON_SCENE));
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
  double worst = 0;
  const double every = 1e-3;
  for (double t = every; t <= sc.time.end * (1 + 1e-12); t += every) {
    run.runTo(std::min(t, sc.time.end));
    const PistonExact ex = study::pistonExact(e, run.time());
    const double s = displacement();
    const double err = trappedPressure(s) / ex.p - 1;
    worst = std::max(worst, std::abs(err));
    std::printf("t %.4f: displacement %.5f (exact %.5f), p %.6g (exact %.6g, error %+.4f)\n", run.time(), s, ex.s,
                trappedPressure(s), ex.p, err);
    EXPECT_NEAR(s, ex.s, 0.01 * ex.s) << "displacement at t = " << run.time();
    EXPECT_LT(std::abs(err), 0.05) << "trapped pressure at t = " << run.time();
  }
  std::printf("largest |p / p_exact - 1| = %.4f\n", worst);
}

}  // namespace
}  // namespace mpmice::test
