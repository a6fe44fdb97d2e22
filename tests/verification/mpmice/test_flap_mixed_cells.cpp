// The perpendicular flap with MPM-ICE (configs/flap_mpmice.yaml, docs/flap.md "Mixed cells"), a
// small, fast variant: the scene at dx = 0.1 (60 x 40 cells, the flap one cell wide: 2 x 20
// particles), run in-process (the monolithic schedule of mpmice) to t = 0.3 s, on the rise to the
// first peak, once with the gas at 1 atm and once at 10 atm (cv, the initial, inflow and outflow
// pressures and the flap's EOS reference pressure raised alike, so rho = 1 at 300 K and the flap is
// stress-free at the ambient pressure, as in docs/flap.md). Issue 14:
//  - the gas's ambient pressure must not move the flap: a uniform pressure level is no load, and
//    at Mach 0.027 / 0.0085 the flow's pressures are the incompressible ones to ~1e-3; the tip
//    displacement at t = 0.3 s at 10 atm within 3 % of the one at 1 atm;
//  - the heat the mixed cells create at the flap's surface (the flap takes it: heat exchange
//    1e15) stays below what the flow dissipates: (p_in - p_out) Q t, the mechanical energy the
//    channel's fixed inflow and outflow pressures take from the flow (130 Pa x 40 m^2/s x t).
// The scene moves the solid's volume with MPM's face transport (coupling.solid_transport: mpm,
// src/ice/face/solid_faces.h). Measured (this test, dx = 0.1, t = 0.3 s, the scene's GIMP): tip ux
// 0.10999 m at 1 atm, 0.11111 m at 10 atm (+1.02 %); flap heat +101.9 J and +91.6 J against the
// flow's 1560 J (quadratic B-splines: 0.13962 / 0.14136 m, +1.25 %; +123.7 / +108.9 J).
// With ICE's face fluxes of the smeared fraction (solid_transport: ice, main 4c8cc7e) it was
// 0.1262 m against 0.0984 m (-22 %) and +570 J / +1463 J (docs/flap.md "Mixed cells").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "coupler/transport/in_memory_transport.h"
#include "core/scene/scene.h"
#include "couplings/volume/schedule/coupling_schedule.h"
#include "serial_mpi.h"

using namespace mpmice;
using namespace mpmice::coupler;

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Replaces the occurrence of `from` in `text`; throws, naming it, when the scene no longer has it.
void replaceOnce(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos)
    throw std::runtime_error(std::string("the flap scene ") + FLAP_SCENE + " no longer holds '" + from + "'");
  text.replace(at, from.size(), to);
}

struct FlapRun {
  double tipUx = std::numeric_limits<double>::quiet_NaN();  // tip x-displacement at the end [m]
  double flapHeat = 0;                                      // change of the flap's m cv T [J]
  double storedWork = 0;                                    // the flap's stored stress work at the end [J]
  double viscousHeat = 0;                                   // the gas's viscous heat over the run [J]
  double time = 0;
  int steps = 0;
};

/// The flap scene at dx = 0.1 to `end` with the gas at `atm` atmospheres (and another
/// ice.face_pressure, another mpm.stress_work when given).
FlapRun runFlap(double atm, double end, const std::string& facePressure = "", const std::string& stressWork = "") {
  std::string y = readFile(FLAP_SCENE);
  char buf[256];
  replaceOnce(y, "spacing: 0.025", "spacing: 0.1");
  std::snprintf(buf, sizeof buf, "end: %.17g", end);
  replaceOnce(y, "end: 5.0", buf);
  const double p = 101325.0 * atm;
  std::snprintf(buf, sizeof buf, "specific_heat: %.17g", p / (0.4 * 300.0));
  replaceOnce(y, "specific_heat: 844.375", buf);
  std::snprintf(buf, sizeof buf, "pressure: %.17g\n", p);
  replaceOnce(y, "pressure: 101325\n", buf);
  std::snprintf(buf, sizeof buf, "pressure: %.17g,", p + 130.0);
  replaceOnce(y, "pressure: 101455,", buf);
  std::snprintf(buf, sizeof buf, "{type: outflow, pressure: %.17g}", p);
  replaceOnce(y, "{type: outflow, pressure: 101325}", buf);
  std::snprintf(buf, sizeof buf, "poissons_ratio: 0.3}\n    eos: {type: solid_bulk, threshold_pressure: %.17g}", p);
  replaceOnce(y, "poissons_ratio: 0.3}", buf);
  core::Scene scene = core::parseScene(y, FLAP_SCENE);
  scene.output.enabled = false;
  if (!facePressure.empty()) scene.ice.face_pressure = facePressure;
  if (!stressWork.empty()) scene.mpm.stress_work = stressWork;
  core::Comm comm{MPI_COMM_SELF};
  mpm::MpmSolver mpm(scene, comm);
  ice::IceSolver ice(scene, comm);
  SolidSide solid(mpm);
  FluidSide fluid(ice, scene);
  const Sides sides{&solid, &fluid};
  InMemoryTransport tr;
  startCoupling(sides, tr);
  const auto schedule = makeSchedule(scene, comm);
  // The tip: the particle nearest to (0, 1), followed by its id.
  const auto& pa = mpm.particles();
  std::size_t tip = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const double d = std::hypot(pa.x[0][i], pa.x[1][i] - 1.0);
    if (d < best) best = d, tip = i;
  }
  const std::int64_t tipId = pa.id[tip];
  const double x0 = pa.x[0][tip];
  FlapRun r;
  const double heat0 = solid.totals().heat;
  double t = 0;
  while (t < end * (1 - 1e-12)) {
    double dt = std::min({solid.stableTimeStep(), fluid.stableTimeStep(), scene.time.dt_max});
    dt = std::min(dt, end - t);
    schedule->step(sides, tr, dt);
    t += dt;
    ++r.steps;
  }
  for (std::size_t i = 0; i < pa.size(); ++i)
    if (pa.id[i] == tipId) r.tipUx = pa.x[0][i] - x0;
  r.flapHeat = solid.totals().heat - heat0;
  r.storedWork = solid.totals().internal;
  r.viscousHeat = ice.viscousHeat();
  r.time = t;
  return r;
}

constexpr double kEnd = 0.3;  // [s]: on the rise to the first peak (0.79 s at this dx)

/// The two runs, made once for both tests.
const std::pair<FlapRun, FlapRun>& runs() {
  static const std::pair<FlapRun, FlapRun> r = [] {
    const FlapRun one = runFlap(1.0, kEnd), ten = runFlap(10.0, kEnd);
    std::printf("flap dx 0.1, t = %.3f s: tip ux 1 atm %.5f m (%d steps), 10 atm %.5f m (%d steps), "
                "difference %.2f %%; flap heat 1 atm %.1f J, 10 atm %.1f J; flow dissipation %.0f J "
                "(the gas's viscous heat 1 atm %.1f J, 10 atm %.1f J)\n",
                one.time, one.tipUx, one.steps, ten.tipUx, ten.steps, 100 * (ten.tipUx - one.tipUx) / one.tipUx,
                one.flapHeat, ten.flapHeat, 130.0 * 40.0 * kEnd, one.viscousHeat, ten.viscousHeat);
    return std::make_pair(one, ten);
  }();
  return r;
}

// The flow's dissipation over the run: the fixed inflow - outflow pressure difference (130 Pa)
// times the volume flux (10 m/s x 4 m) times the time, and as the gas's viscous heat measures it
// (ICE's viscous heating, 6 Dec 2026: 1511.5 J at 1 atm, 1732.5 J at 10 atm against the estimate's
// 1560 J). Passes on main (4c8cc7e): 570 J and 1463 J against 1560 J (the energy closure of the
// coupled step holds the surface heat down; the 5.5 MJ of docs/flap.md's older figures are gone);
// 163.0 J and 146.7 J measured on f625dc9 (with the gas's viscous heat).
TEST(FlapMixedCells, SurfaceMakesLessHeatThanTheFlowDissipates) {
  const auto& [one, ten] = runs();
  const double dissipation = 130.0 * 40.0 * kEnd;
  EXPECT_LT(std::abs(one.flapHeat), dissipation) << "1 atm: heat created at the surface";
  EXPECT_LT(std::abs(ten.flapHeat), dissipation) << "10 atm: heat created at the surface";
  EXPECT_LT(std::abs(one.flapHeat), one.viscousHeat) << "1 atm: against the gas's own viscous heat";
  EXPECT_LT(std::abs(ten.flapHeat), ten.viscousHeat) << "10 atm: against the gas's own viscous heat";
}

// The tip at 10 atm within 3 % of the tip at 1 atm (issue 14): a uniform pressure level is no
// load. Measured +1.02 % with GIMP (0.11111 against 0.10999 m); bspline2 +1.25 % (0.14136 against
// 0.13962 m; +0.79 % before the flap's solver_tolerance
// 1e-6). With ICE's face fluxes of the smeared fraction (solid_transport: ice) -22 %: the gas in
// the mixed cells was squeezed by the solid volume the node-to-cell average moved into them, with
// the stiffness gamma p.
TEST(FlapMixedCells, AmbientPressureDoesNotMoveTheFlap) {
  const auto& [one, ten] = runs();
  ASSERT_GT(one.tipUx, 0.05) << "the flap bends downstream by t = 0.3 s";
  EXPECT_LT(std::abs(ten.tipUx - one.tipUx), 0.03 * one.tipUx)
      << "tip ux at 10 atm " << ten.tipUx << " m against " << one.tipUx << " m at 1 atm";
}

// The flap's stored stress work as the grid counts it (the scene's `auto` in a coupled run: the
// internal forces' work on the nodes, which MPM's health check reads) follows the models' own
// stress power (`material`): the exchange's increments at the surface nodes deform the flap after
// the grid update, and the count takes the velocity the step ends with (docs/mpm.md "Stress
// work"). Taken before the increments it fell behind: 6.16 J against 7.63 J at t = 0.3 s (-19 %;
// bspline2 7.19 J against 8.46 J, -15 %), and with bspline2 at dx 0.05 below zero by t = 1.2 s
// (the 5 s run at dx 0.025 stopped at 4.80 s on it). Measured with the end velocity: 7.91 J
// against 7.62 J (+3.8 %; bspline2 +2.7 %; the two counts differ by the time step's truncation).
TEST(FlapMixedCells, GridStressWorkFollowsTheModelsStressPower) {
  const FlapRun& grid = runs().first;
  const FlapRun material = runFlap(1.0, kEnd, "", "material");
  std::printf("flap dx 0.1, t = %.3f s: stored stress work, grid count %.4f J, models' %.4f J (%+.2f %%)\n",
              grid.time, grid.storedWork, material.storedWork,
              100 * (grid.storedWork - material.storedWork) / material.storedWork);
  ASSERT_GT(material.storedWork, 1.0) << "the flap is loaded by t = 0.3 s";
  EXPECT_LT(std::abs(grid.storedWork - material.storedWork), 0.05 * material.storedWork)
      << "grid count " << grid.storedWork << " J against the models' " << material.storedWork << " J";
}

// The same with ice.face_pressure: riemann_low_mach (the Riemann terms at every fluid face, scaled
// down at low Mach numbers and small jumps): measured +0.19 % with GIMP (0.11268 against 0.11247 m;
// bspline2 +0.46 %, 0.14339 against 0.14273 m). The
// unscaled riemann fails it (+39 %: 0.27023 against 0.19444 m, in 5.5 times the steps).
TEST(FlapMixedCells, AmbientPressureDoesNotMoveTheFlapWithRiemannLowMach) {
  const FlapRun one = runFlap(1.0, kEnd, "riemann_low_mach"), ten = runFlap(10.0, kEnd, "riemann_low_mach");
  std::printf("riemann_low_mach: tip ux 1 atm %.5f m (%d steps), 10 atm %.5f m (%d steps), difference %.2f %%\n",
              one.tipUx, one.steps, ten.tipUx, ten.steps, 100 * (ten.tipUx - one.tipUx) / one.tipUx);
  ASSERT_GT(one.tipUx, 0.05) << "the flap bends downstream by t = 0.3 s";
  EXPECT_LT(std::abs(ten.tipUx - one.tipUx), 0.03 * one.tipUx)
      << "tip ux at 10 atm " << ten.tipUx << " m against " << one.tipUx << " m at 1 atm";
}

}  // namespace
