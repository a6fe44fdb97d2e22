// Two-material tests: the water-air shock tube (stiffened gas water at 1 GPa against air at
// 1 bar, interface at x = 0.7, t = 240 us) against the exact two-gas Riemann solution, and the
// advection of a water column in air at uniform velocity and pressure (pressure and velocity must
// stay uniform to round-off).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "ice_shock_cases.h"
#include "ice_test_scenes.h"
#include "test_comm.h"

using namespace mpmice;

namespace {

core::Scene waterAir(int n, const std::string& advection) {
  core::Scene s;
  s.name = "water_air";
  s.mesh = core::Mesh(1, {0, 0, 0}, {1.0 / n, 1, 1}, {n, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Outflow;
  s.time.end = 240e-6;
  s.materials = {test::stiffenedGas("water", 4.4, 6e8), test::idealGas("air")};
  s.geometry = {test::region("water", test::box({0, 0, 0}, {0.7, 1, 1}), {{"water", 1.0}}, 1e9, 1000),
                test::region("air", test::box({0.7, -1, -1}, {2, 2, 2}), {{"air", 1.0}}, 1e5, 50)};
  s.ice.advection = advection;
  return s;
}

}  // namespace

TEST(IceWaterAir, ShockTubePositionsWithinTwoCells) {
  const int n = 400;
  const double dx = 1.0 / n, t = 240e-6;
  const test::ExactRiemann ex({1000, 0, 1e9}, {50, 0, 1e5}, {4.4, 6e8}, {1.4, 0});
  EXPECT_NEAR(ex.pStar(), 1.419e7, 0.01e7);
  EXPECT_NEAR(ex.uStar(), 482.6, 1.0);
  for (const char* adv : {"first_order", "second_order"}) {
    ice::IceSolver s(waterAir(n, adv), test::comm());
    test::runToEnd(s, t);
    double minP = 1e300, minTheta = 1e300;
    double contact = -1, shock = -1;
    const double pHalf = 0.5 * (ex.pStar() + 1e5);
    core::forEach(s.ownedBox(), [&](int i, int j, int k) {
      minP = std::min(minP, s.pressure()(i, j, k));
      for (int r = 0; r < 2; ++r) minTheta = std::min(minTheta, s.state().mat[r].theta(i, j, k));
      const double x = s.mesh().cellCenter(0, i);
      if (contact < 0 && s.state().mat[0].theta(i, j, k) < 0.5) contact = x - 0.5 * dx;
      if (s.pressure()(i, j, k) > pHalf) shock = x + 0.5 * dx;
    });
    const double xContact = 0.7 + ex.uStar() * t, xShock = 0.7 + ex.shockSpeed(+1) * t;
    std::printf("  %s: %ld steps, contact %.4f (exact %.4f), air shock %.4f (exact %.4f), min p %.3e, min theta %.2e\n",
                adv, s.steps(), contact, xContact, shock, xShock, minP, minTheta);
    EXPECT_GT(minP, 0.0);
    EXPECT_GE(minTheta, 0.0);
    EXPECT_NEAR(contact, xContact, 2 * dx);
    EXPECT_NEAR(shock, xShock, 2 * dx);
  }
}

TEST(IceWaterAir, InterfaceAdvectionKeepsPressureUniform) {
  for (const char* adv : {"first_order", "second_order"}) {
    core::Scene s;
    s.name = "interface_advection";
    s.mesh = core::Mesh(1, {0, 0, 0}, {0.01, 1, 1}, {100, 1, 1});
    for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
    s.time.end = 1e-3;
    s.materials = {test::stiffenedGas("water", 4.4, 6e8), test::idealGas("air")};
    s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 1e5, 1.2, {100, 0, 0}),
                  test::region("water", test::box({0.4, -1, -1}, {0.6, 2, 2}), {{"water", 1.0}}, 1e5, 1000,
                               {100, 0, 0})};
    s.ice.advection = adv;
    ice::IceSolver sol(s, test::comm());
    test::runToEnd(sol, s.time.end);
    double dp = 0, du = 0, waterMass = 0;
    core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
      dp = std::max(dp, std::abs(sol.pressure()(i, j, k) - 1e5) / 1e5);
      for (int r = 0; r < 2; ++r)
        if (sol.state().mat[r].mass(i, j, k) > 0)
          du = std::max(du, std::abs(sol.state().mat[r].vel(i, j, k, 0) - 100) / 100);
      waterMass += sol.state().mat[0].mass(i, j, k);
    });
    std::printf("  %s: %ld steps, max |p - p0|/p0 = %.2e, max |u - u0|/u0 = %.2e, water mass %.15g\n", adv,
                sol.steps(), dp, du, waterMass);
    // Round-off level: water's stiffness turns a density round-off of 1e-16 into a pressure change
    // of 1e-16 rho c^2 / p = 2.6e-12 p at 1 bar, which random-walks over the steps.
    EXPECT_LT(dp, 1e-10);
    EXPECT_LT(du, 1e-12);
    EXPECT_NEAR(waterMass, 200.0, 1e-9);
  }
}

TEST(IceWaterAir, SemiImplicitRunsAndKeepsThePositions) {
  const int n = 400;
  const double dx = 1.0 / n, t = 240e-6;
  const test::ExactRiemann ex({1000, 0, 1e9}, {50, 0, 1e5}, {4.4, 6e8}, {1.4, 0});
  core::Scene sc = waterAir(n, "second_order");
  sc.ice.pressure_solver = "semi_implicit";
  ice::IceSolver s(sc, test::comm());
  test::runToEnd(s, t);
  double minP = 1e300, contact = -1, shock = -1;
  const double pHalf = 0.5 * (ex.pStar() + 1e5);
  core::forEach(s.ownedBox(), [&](int i, int j, int k) {
    minP = std::min(minP, s.pressure()(i, j, k));
    const double x = s.mesh().cellCenter(0, i);
    if (contact < 0 && s.state().mat[0].theta(i, j, k) < 0.5) contact = x - 0.5 * dx;
    if (s.pressure()(i, j, k) > pHalf) shock = x + 0.5 * dx;
  });
  std::printf("  semi-implicit: %ld steps, contact %.4f (exact %.4f), air shock %.4f (exact %.4f), min p %.3e\n",
              s.steps(), contact, 0.7 + ex.uStar() * t, shock, 0.7 + ex.shockSpeed(+1) * t, minP);
  EXPECT_GT(minP, 0.0);
  EXPECT_NEAR(contact, 0.7 + ex.uStar() * t, 2 * dx);
  EXPECT_NEAR(shock, 0.7 + ex.shockSpeed(+1) * t, 2 * dx);
}

namespace {

struct RealRatioRun {
  bool completed = false;
  std::string error;
  double l1 = 0, minThetaSum = 0;
  long steps = 0;
};

// Water (stiffened gas 4.4 / 6e8, 1000 kg/m^3, 1e9 Pa) against air at its real density
// (1.2 kg/m^3, 1e5 Pa; ratio ~830), default settings but ice.trace_mass_fraction = Y, n cells,
// to t = 240 us, with the health check after every step (as the programs run it).
RealRatioRun runRealRatio(int n, double Y, const test::TubeOptions& o = {}) {
  const test::ShockCase c = test::waterAirRealDensity();
  core::Scene sc = test::shockCaseScene(c, n, o);
  sc.ice.trace_mass_fraction = Y;
  const test::ExactRiemann ex(c.L, c.R, c.gl, c.gr);
  RealRatioRun r;
  try {
    ice::IceSolver s(sc, test::comm());
    while (s.time() < c.t * (1 - 1e-12)) {
      s.step();
      ice::checkHealth(s);
    }
    r.steps = s.steps();
    r.l1 = test::l1Density(s, [&](double x) { return ex.sample((x - c.x0) / c.t).rho; });
    r.completed = true;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

}  // namespace

// Issue 12: water against air at the real density ratio completes with the default settings and
// converges to the exact Riemann solution (docs/ice.md "Traces"). Measured L1(rho) 9.33 / 5.20 /
// 3.41 kg/m^2 at 200 / 400 / 800 cells (fitted order 0.73) with the trace rule alone, bounds 10 %
// above; 9.09 / 5.74 / 3.52 with the Riemann face velocity response merged beside it (that change
// alone completes the default settings, the rule or not). The rule is what completes first-order
// advection: without it (ice.trace_mass_fraction: 0) the 400-cell first-order run stops with an
// error naming a cell (the air left in the water's cells by the smeared contact must fill the
// water's volume deficit at p > 0); with it the same run completes.
TEST(IceWaterAir, RealDensityRatioCompletesAndConverges) {
  const test::ShockCase c = test::waterAirRealDensity();
  const test::ExactRiemann ex(c.L, c.R, c.gl, c.gr);
  EXPECT_NEAR(ex.pStar(), 5.407e5, 0.001e5);
  EXPECT_NEAR(ex.uStar(), 491.9, 0.1);
  const std::vector<int> ns = {200, 400, 800};
  const std::vector<double> bound = {10.3, 5.75, 3.75};
  std::vector<double> err;
  for (std::size_t a = 0; a < ns.size(); ++a) {
    const RealRatioRun r = runRealRatio(ns[a], core::IceOptions{}.trace_mass_fraction);
    std::printf("  %d cells: %s, %ld steps, L1(rho) %.4g kg/m^2 %s\n", ns[a], r.completed ? "completed" : "STOPPED",
                r.steps, r.l1, r.error.c_str());
    ASSERT_TRUE(r.completed) << r.error;
    EXPECT_LT(r.l1, bound[a]);
    err.push_back(r.l1);
  }
  const double order = test::fittedOrder(ns, err);
  std::printf("  fitted order %.3f\n", order);
  EXPECT_GT(order, 0.65);
  EXPECT_LT(err[2], err[1]);
  EXPECT_LT(err[1], err[0]);
  test::TubeOptions first;
  first.advection = "first_order";
  const RealRatioRun on = runRealRatio(400, core::IceOptions{}.trace_mass_fraction, first);
  std::printf("  first order, 400 cells, with the trace rule: %s\n", on.completed ? "completed" : on.error.c_str());
  EXPECT_TRUE(on.completed) << on.error;
  const RealRatioRun off = runRealRatio(400, 0.0, first);
  std::printf("  first order, 400 cells, without the trace rule: %s\n", off.completed ? "completed" : off.error.c_str());
  EXPECT_FALSE(off.completed);
  EXPECT_NE(off.error.find("in cell ("), std::string::npos) << off.error;
}

// Issue 12, the semi-implicit water-air stops (docs/ice.md "Equilibrium with work"): with the
// semi-implicit pressure and van Leer the fixed-energy equilibrium compresses the air share of the
// contact cells by the water's overshooting pressure without work and charges the work back on the
// expansion: air below 0 K at step 17-32 at every resolution. With ice.equilibrium: with_work the
// same runs complete and converge; measured L1(rho) 33.18 / 20.59 / 12.96 / 8.17 kg/m^2 at 100 /
// 200 / 400 / 800 cells (order 0.67), bounds 5 % above at 200 and 400 (the explicit default is
// 9.09 / 5.74: the semi-implicit step runs at a water acoustic CFL of 2-4).
// Since the positivity blend of the advection (3 Dec 2026, src/ice/advection/advection_phase.cpp:
// the limited face values of a donor's outgoing faces may no longer take more than 90 % of its
// specific energy or volume), the fixed-energy run completes too: L1(rho) 18.30 at 200 cells
// (bound 5 % above); before, air below 0 K at step 17-32.
TEST(IceWaterAir, SemiImplicitVanLeerCompletesWithAndWithoutWork) {
  test::TubeOptions o;
  o.pressure = "semi_implicit";
  o.limiter = "van_leer";
  const double Y = core::IceOptions{}.trace_mass_fraction;
  const RealRatioRun fixed = runRealRatio(200, Y, o);
  std::printf("  semi-implicit, van Leer, fixed_energy, 200 cells: %s, L1(rho) %.4g kg/m^2\n",
              fixed.completed ? "completed" : fixed.error.c_str(), fixed.l1);
  EXPECT_TRUE(fixed.completed) << fixed.error;
  EXPECT_LT(fixed.l1, 19.2);
  o.equilibrium = "with_work";
  const std::vector<int> ns = {200, 400};
  const std::vector<double> bound = {21.6, 13.6};
  std::vector<double> err;
  for (std::size_t a = 0; a < ns.size(); ++a) {
    const RealRatioRun r = runRealRatio(ns[a], Y, o);
    std::printf("  semi-implicit, van Leer, with_work, %d cells: %s, %ld steps, L1(rho) %.4g kg/m^2\n", ns[a],
                r.completed ? "completed" : r.error.c_str(), r.steps, r.l1);
    ASSERT_TRUE(r.completed) << r.error;
    EXPECT_LT(r.l1, bound[a]);
    err.push_back(r.l1);
  }
  EXPECT_LT(err[1], 0.7 * err[0]);  // converging (measured ratio 0.63)
}

// Where the water-air overshoot is made (docs/ice.md "Water-air: start-up or scheme"): the water
// already in its star state driving the air (contact and air shock only) overshoots behind the
// air shock when it starts as a sharp step (+2.59 % in the air's density at 800 cells, explicit:
// the contact and the newborn shock share a cell whose single pressure cannot hold p*), not when it
// starts from the exact solution with its contact 4 cells on (at most +0.15 % in both pressures at
// 400 and 800 cells), and the contact alone (both star states) moves without disturbing the
// pressure. So the start-up is the error, the mixed cells' transport of a moving contact is not.
TEST(IceWaterAir, TheOvershootIsTheStartUpNotTheMovingContact) {
  for (const char* pressure : {"explicit", "semi_implicit"}) {
    test::TubeOptions o;
    o.pressure = pressure;
    for (const int n : {400, 800}) {
      const test::ShockResult sharp = test::runShockCase(test::waterPiston(), n, o, 0);
      const test::ShockResult exact = test::runShockCase(test::waterPiston(), n, o, 4);
      std::printf("%s %d cells: water piston from a step: air %+.2f %%, p %+.2f %%; from the exact solution: air "
                  "%+.2f %%, p %+.2f %%\n",
                  pressure, n, sharp.overRhoOwn, sharp.overP, exact.overRhoOwn, exact.overP);
      ASSERT_TRUE(sharp.completed && exact.completed) << sharp.error << exact.error;
      EXPECT_LT(exact.overRhoOwn, 0.5) << pressure << " " << n;
      EXPECT_LT(exact.overP, 0.5) << pressure << " " << n;
      if (n == 800) {
        EXPECT_GT(sharp.overRhoOwn, 1.5) << pressure;  // the start-up's excess, measured +2.4 .. +2.6 %
      }
    }
    const test::ShockResult contact = test::runShockCase(test::movingContact(), 800, o, 0);
    ASSERT_TRUE(contact.completed) << contact.error;
    const double pStar = test::waterAirStar(1).p;
    EXPECT_NEAR(contact.minP, pStar, 1e-9 * pStar) << pressure;
  }
}

// An absent fluid (no mass in a cell) keeps its placeholder state: the air in the water's cells,
// deep in the rarefaction the water-air tube sends left, is not accelerated by the pressure gradient
// nor worked on (docs/ice.md "Absent fluids keep their placeholder state": so accelerated and worked
// on at its absent density, an air's state grew 4-5 times a step to overflow in the water-filled
// foam run and made the water's energy NaN).
TEST(IceWaterAir, AnAbsentFluidKeepsItsPlaceholderState) {
  const int n = 100;
  ice::IceSolver s(waterAir(n, "second_order"), test::comm());
  const int i = 30;  // x = 0.305: reached by the rarefaction's head (~2300 m/s) by 100 us
  const bool mine = s.ownedBox().contains(i, 0, 0);
  const auto& air = s.state().mat[1];
  double e0 = 0, u0 = 0;
  if (mine) {
    ASSERT_EQ(air.mass(i, 0, 0), 0.0);
    e0 = air.eint(i, 0, 0), u0 = air.vel(i, 0, 0, 0);
  }
  double pMin = 1e300;
  while (s.time() < 150e-6) {
    s.step();
    if (mine) pMin = std::min(pMin, s.pressure()(i, 0, 0));
  }
  if (mine) {
    EXPECT_EQ(air.mass(i, 0, 0), 0.0);
    EXPECT_LT(pMin, 0.9e9);  // the rarefaction passed: a pressure gradient acted on the cell
    EXPECT_EQ(air.vel(i, 0, 0, 0), u0);
    EXPECT_EQ(air.eint(i, 0, 0), e0);
    std::printf("absent air at x = 0.305 after %ld steps (water down to %.3e Pa there): u %.3g m/s, e %.6g J/kg\n",
                s.steps(), pMin, air.vel(i, 0, 0, 0), air.eint(i, 0, 0));
  }
}
