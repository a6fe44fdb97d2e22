// The adiabatic piston through the coupling (configs/piston.yaml, Uintah's pistonVal problem): a
// free copper piston moving at v into trapped air, the gas started in the quasi-static state.
// Exact: the quasi-static answer with the piston's own dynamics (it is free, so it decelerates),
//   s' = v,  M v' = -(p - p_L),  p = p0 (h0 / (h0 - s))^gamma,  p_L = p0 (hL0 / (hL0 + s))^gamma,
// integrated by RK4 to round-off (src/study/reference/piston.h, the study's `piston` reference).
// Asserted: the piston's displacement, and the mean pressure of the trapped gas (its pure-gas
// cells) against p(t) every millisecond to 20 ms: within the goal of 1 % (issue 12) at the scene's
// spacing (50 cells), and converging at four spacings (25 to 200 cells, the one scene with
// `mesh.spacing` set: its gas velocity profile is geometric, so every mesh starts the same flow).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "coupled_run.h"
#include "study/reference/piston.h"
#include "serial_mpi.h"

namespace mpmice::test {
namespace {

using study::PistonExact;
using study::PistonSetup;

// The goal of issue 12 (1 %) at the scene's spacing, p(t) every millisecond and the final pressure
// (docs/verification-coupled.md, "The piston": measured 0.15 % worst, 0.07 % final, displacement 0.00 %;
// 0.53 % at 25 cells, the shipped spacing until 3 Dec 2026; 0.89 / 0.75 % and 2.89 % before the
// held-cell face velocity fix of issue 12's per-step error).
constexpr double kGoal = 0.01;

/// configs/piston.yaml with `mesh.spacing` set to dx.
core::Scene pistonAt(double dx) {
  std::ifstream in(PISTON_SCENE);
  std::stringstream text;
  text << in.rdbuf();
  std::ostringstream spacing;
  spacing << "spacing: " << dx << " ";
  const std::regex line("spacing: [0-9.eE+-]+ ");
  EXPECT_TRUE(std::regex_search(text.str(), line)) << "configs/piston.yaml has no `spacing:` line to set";
  const std::string yaml = std::regex_replace(text.str(), line, spacing.str());
  return core::parseScene(yaml, PISTON_SCENE);
}

/// One run: the largest and the final |p / p_exact - 1| of the trapped gas (every millisecond) and
/// the largest relative displacement error.
struct PistonErrors {
  double worst = 0, final = 0, displacement = 0;
};

PistonErrors runPiston(core::Scene scene, double cfl = 0,
                       const std::function<void(const CoupledRun&)>& afterStep = {}) {
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
  std::printf("%s (%d cells)\n", sc.file.c_str(), sc.mesh.cells()[0]);
  for (double t = every; t <= sc.time.end * (1 + 1e-12); t += every) {
    run.runTo(std::min(t, sc.time.end), [&] {
      if (afterStep) afterStep(run);
    });
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
  const PistonErrors r = runPiston(core::loadScene(PISTON_SCENE));
  EXPECT_LT(r.displacement, 0.01);
  EXPECT_LT(r.worst, kGoal) << "p(t) against the adiabat, every millisecond";
  EXPECT_LT(r.final, kGoal) << "the final pressure";
}

// The stability map's point CFL 0.7 (docs/stability.md): it used to end with the copper's stored
// stress work at -4.6e8 J and the gas at 14 times the exact pressure (a sawtooth the GIMP / FLIP
// step grows beyond CFL ~0.68 at the copper's free faces; then the MPM health check stopped it at
// step 80). The MPM step now takes at most its stable CFL number (mpm_constants.h, kMaxStableCfl
// 0.5) and the run is the piston again, within the goal: measured 0.15 % worst, 0.07 % final, as at CFL 0.4
// (0.76 / 0.63 % against 0.89 / 0.75 % before the held-cell face velocity fix).
TEST(AdiabaticPiston, AtCfl07RunsWithinTheMpmStepsLimit) {
  const PistonErrors r = runPiston(core::loadScene(PISTON_SCENE), 0.7);
  EXPECT_LT(r.displacement, 0.01);
  EXPECT_LT(r.worst, kGoal) << "p(t) against the adiabat, every millisecond";
  EXPECT_LT(r.final, kGoal) << "the final pressure";
}

// Issue 12's per-step error: the final error was 0.75 / 1.24 / 1.81 / 2.30 % at CFL 0.4 / 0.2 /
// 0.1 / 0.05 (the more steps, the more of the surface cells' gas the piston pushed into the pure
// gas), because the face velocity beside a cell where the exchange holds the gas to the copper
// answered a pressure jump only with dt v grad p (docs/verification-coupled.md, "The error grew as
// the step shrank"). With the acoustic response there: 0.073 / 0.072 / 0.071 / 0.073 % final
// (0.15 % worst at each). Asserted: at CFL 0.1 and 0.05 the goal holds, and the final and largest
// errors are those of CFL 0.4 to within 0.1 % of p (before: +1.06 and +1.55 points).
TEST(AdiabaticPiston, ErrorDoesNotGrowAsTheStepShrinks) {
  const PistonErrors ref = runPiston(core::loadScene(PISTON_SCENE), 0.4);
  for (const double cfl : {0.1, 0.05}) {
    const PistonErrors r = runPiston(core::loadScene(PISTON_SCENE), cfl);
    EXPECT_LT(r.displacement, 0.01) << "CFL " << cfl;
    EXPECT_LT(r.worst, kGoal) << "CFL " << cfl << ": p(t) against the adiabat, every millisecond";
    EXPECT_LT(r.final, kGoal) << "CFL " << cfl << ": the final pressure";
    EXPECT_NEAR(r.final, ref.final, 1e-3) << "CFL " << cfl << " against CFL 0.4: the final pressure";
    EXPECT_NEAR(r.worst, ref.worst, 1e-3) << "CFL " << cfl << " against CFL 0.4: p(t)";
  }
}

// Issue 12, "stable and honest at the extremes": below CFL 0.4 the finer meshes stopped (100 cells
// at CFL 0.05 at 2.90 ms, 200 cells at CFL 0.2 / 0.1 / 0.05 at 1.77 / 1.23 / 1.10 ms) with the trace
// of air in a cell the copper fills above 1e9 K. The trace followed the cell's pressure, which the
// copper's ringing swung between ~0 (its EOS's tension branch) and several MPa: a mode of ~7 cells
// grew in the copper e-fold every ~0.1 ms (its cells' velocities 10 +- 2e-4 m/s at 0.1 ms, +- 0.15
// m/s at 1 ms at CFL 0.1), because the mean-stress correction took the pressure interpolated from
// the neighbouring cells inside the solid as well (docs/verification-coupled.md, "The piston
// stopped at small steps"; the fix: src/mpm/cell/node_cell_operators.cpp). Asserted, to 2 ms at
// 200 cells, CFL 0.1 and to 4 ms at 100 cells, CFL 0.05 (each past its old stop): the run
// completes, the piston's particles keep their velocities
// within an atmosphere's acoustic velocity jump in copper, p0 / (rho c) (c its longitudinal wave
// speed), of each other (measured 7.5e-4 and 1.5e-3 m/s, as at CFL 0.4: 6.8e-4 and 1.3e-3; before,
// the copper's cells spread to +- 0.15 m/s by 1 ms), and the pressure error is that of CFL 0.4 to
// within 1e-4 of p.
TEST(AdiabaticPiston, CopperStaysQuietAtSmallStepsOnFinerMeshes) {
  struct Case {
    double dx, cfl, end;
  };
  for (const Case c : {Case{0.005, 0.1, 0.002}, Case{0.01, 0.05, 0.004}}) {
    core::Scene scene = pistonAt(c.dx);
    scene.time.end = c.end;
    const core::MaterialSpec& cu = scene.materials[static_cast<std::size_t>(scene.materialIndex("copper"))];
    const double K = cu.constitutive.get("bulk_modulus", 0.0), G = cu.constitutive.get("shear_modulus", 0.0);
    const double acoustic = study::pistonSetup(scene).p0 / std::sqrt(cu.density * (K + 4.0 * G / 3.0));
    // The largest spread of the piston's particle velocities over the run.
    const auto spreadOf = [](double& spread) {
      return [&spread](const CoupledRun& run) {
        const auto& parts = run.mpm.particles();
        double lo = parts.v[0][0], hi = lo;
        for (std::size_t i = 0; i < parts.size(); ++i) {
          lo = std::min(lo, parts.v[0][i]);
          hi = std::max(hi, parts.v[0][i]);
        }
        spread = std::max(spread, hi - lo);
      };
    };
    double spread = 0, spreadRef = 0;
    const PistonErrors r = runPiston(scene, c.cfl, spreadOf(spread));
    const PistonErrors ref = runPiston(scene, 0.4, spreadOf(spreadRef));
    std::printf("dx %g, CFL %g to %g s: the piston's particle velocities within %.3g m/s of each other (bound p0 / "
                "(rho c) = %.3g m/s; at CFL 0.4 %.3g m/s); p(t) error %.2e, at CFL 0.4 %.2e\n",
                c.dx, c.cfl, c.end, spread, acoustic, spreadRef, r.worst, ref.worst);
    EXPECT_GT(K, 0.0);
    EXPECT_LT(spread, acoustic) << "dx " << c.dx << ", CFL " << c.cfl << ": the copper rings";
    EXPECT_LT(r.displacement, 0.01) << "dx " << c.dx << ", CFL " << c.cfl;
    EXPECT_NEAR(r.worst, ref.worst, 1e-4) << "dx " << c.dx << ", CFL " << c.cfl << " against CFL 0.4: p(t)";
  }
}

// The scene at 25, 50, 100 and 200 cells to 20 ms (5 to 40 cells of travel). Before MPM's face
// transport (solid_transport ice) the error grew with refinement (4.3, 4.9, 7.4 % at 25-100: the
// gas advected across the moving piston's surface cells); before the trace temperature rule the
// finer meshes stopped with the trace gas in the copper's cells at 1e9 K. Measured 0.53, 0.15,
// 0.04, 0.01 % (order 2.06 over 50 -> 200 cells; 2.89, 0.89, 0.24, 0.06 %, order 1.95, before
// the held-cell face velocity fix).
// Asserted: each run completes with the displacement within 1 %, the error falls at every
// refinement, and the fitted order of the largest p(t) error over 50 -> 200 cells is at least 1.
TEST(AdiabaticPiston, ConvergesAtFourSpacings) {
  const double dx[4] = {0.04, 0.02, 0.01, 0.005};
  double worst[4];
  for (int k = 0; k < 4; ++k) {
    const PistonErrors r = runPiston(pistonAt(dx[k]));
    worst[k] = r.worst;
    EXPECT_LT(r.displacement, 0.01) << "dx " << dx[k];
    if (k > 0) {
      EXPECT_LT(worst[k], worst[k - 1]) << "dx " << dx[k];
    }
  }
  const double order = std::log(worst[1] / worst[3]) / std::log(4.0);
  std::printf("largest p(t) errors %.4f %.4f %.4f %.4f at 25, 50, 100, 200 cells: order %.2f (50 -> 200)\n",
              worst[0], worst[1], worst[2], worst[3], order);
  EXPECT_GE(order, 1.0);
}

}  // namespace
}  // namespace mpmice::test
