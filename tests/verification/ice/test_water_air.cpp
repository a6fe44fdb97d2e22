// Two-material tests: the water-air shock tube (stiffened gas water at 1 GPa against air at
// 1 bar, interface at x = 0.7, t = 240 us) against the exact two-gas Riemann solution, and the
// advection of a water column in air at uniform velocity and pressure (pressure and velocity must
// stay uniform to round-off).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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
