// ICE with its default settings (second order, van Leer, explicit, face_pressure: riemann) on Sod
// and Toro's tests 1-5 at 100, 200, 400, 800 and 1600 cells (issue 12's resolutions; the full
// sweep over every setting is scripts/ice_shock_sweep.sh, docs/ice.md "Shocks"): every run
// completes through the health check, the overshoot behind each shock stays below 2 % of the jump,
// test 5's stationary contact stays below 1e-3 of the wave speed, and L1(rho) falls with
// refinement; water against air at the real density ratio likewise (the air shock).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ice_shock_cases.h"

using namespace mpmice;

namespace {
const int kCells[5] = {100, 200, 400, 800, 1600};
// Issue 12's bounds: overshoot behind a shock <= 2 % of the jump, |u - u*| at a stationary
// contact < 1e-3 of the fastest wave speed.
constexpr double kOvershoot = 2.0;
constexpr double kContact = 1e-3;
// (Test 3's density at 200 cells was +3.03 %, an entropy deficit behind the shock, and held to
// 3.4 % until the entropy-bounded face state of the advection, docs/ice.md "Shocks", fix 3:
// now +0.36 %, under the common 2 %.)
}  // namespace

TEST(IceShockDefaults, ToroSuiteCompletesWithoutOvershootBehindTheShocks) {
  for (const test::ShockCase& c : test::toroCases()) {
    std::vector<double> err;
    for (const int n : kCells) {
      const test::ShockResult r = test::runShockCase(c, n, {});
      ASSERT_TRUE(r.completed) << c.name << " " << n << ": " << r.error;
      std::printf("  %s %d cells: L1(rho) %.4e, overshoot rho %+.2f %% p %+.2f %%, contact |u - u*| %.1e of the wave speed\n",
                  c.name.c_str(), n, r.l1, r.overRho, r.overP, r.contactU);
      EXPECT_LT(r.overRho, kOvershoot) << c.name << " " << n;
      EXPECT_LT(r.overP, kOvershoot) << c.name << " " << n;
      if (c.name == "toro5") {
        EXPECT_LT(r.contactU, kContact) << n;  // the stationary contact
      }
      EXPECT_GT(r.minP, 0.0) << c.name << " " << n;
      err.push_back(r.l1);
    }
    for (std::size_t i = 1; i < err.size(); ++i) EXPECT_LT(err[i], err[i - 1]) << c.name;
  }
}

// Water against air at the real density ratio (the two-material case of the sweep) with the
// default settings at 100..1600 cells: completes, and behind the air shock the air's own density
// and the pressure stay below 2 % of the jump at every resolution. The mixture density is held to
// the same 2 % from 200 cells; at 100 cells the air shock is 2-3 cells ahead of the smeared
// contact and the measuring window holds water (+26.9 %, docs/ice.md "Traces").
TEST(IceShockDefaults, WaterAirRealDensityWithoutOvershootBehindTheAirShock) {
  const test::ShockCase c = test::waterAirRealDensity();
  std::vector<double> err;
  for (const int n : kCells) {
    const test::ShockResult r = test::runShockCase(c, n, {});
    ASSERT_TRUE(r.completed) << n << ": " << r.error;
    std::printf("  %d cells: L1(rho) %.4e, overshoot air rho %+.2f %%, mixture rho %+.2f %%, p %+.2f %%\n", n, r.l1,
                r.overRhoOwn, r.overRho, r.overP);
    EXPECT_LT(r.overRhoOwn, kOvershoot) << n;
    EXPECT_LT(r.overP, kOvershoot) << n;
    if (n > 100) {
      EXPECT_LT(r.overRho, kOvershoot) << n;
    }
    err.push_back(r.l1);  // (no p > 0: the water's start-up tension is admissible, docs/ice.md)
  }
  for (std::size_t i = 1; i < err.size(); ++i) EXPECT_LT(err[i], err[i - 1]);
}

// time.cfl above 0.7 (the scene allows up to 1): where the flow is slow against the sound speed the
// explicit step's acoustic Courant number is held at kMaxAcousticCourant = 0.7, above which the
// step is linearly unstable (ice_constants.h). Water's rarefaction and water against air at CFL 1
// then give the answers of CFL 0.7. Measured without the bound (4 Dec 2026): L1 at 1600 cells
// 2.12 against 1.13 (the rarefaction) and 9.17 against 2.42 (water-air, whose water went to -4e6 Pa
// at the contact and the air 18 % below its shocked density), an odd-even pressure oscillation
// in the rarefaction from step 30 on.
TEST(IceShockDefaults, WaterAtCflOneKeepsTheAnswersOfCfl07) {
  for (const test::ShockCase& c : {test::waterRarefaction(), test::waterAirRealDensity()})
    for (const int n : {400, 1600}) {
      test::TubeOptions o07, o10;
      o07.cfl = 0.7;
      o10.cfl = 1.0;
      const test::ShockResult a = test::runShockCase(c, n, o07), b = test::runShockCase(c, n, o10);
      ASSERT_TRUE(a.completed && b.completed) << c.name << " " << n << ": " << a.error << b.error;
      std::printf("  %s %d cells: L1(rho) %.4e at CFL 0.7, %.4e at CFL 1; overshoot p %+.2f / %+.2f %%\n",
                  c.name.c_str(), n, a.l1, b.l1, a.overP, b.overP);
      EXPECT_LT(b.l1, 1.05 * a.l1) << c.name << " " << n;
      EXPECT_LT(b.overP, kOvershoot) << c.name << " " << n;
      if (c.twoMaterials) {
        EXPECT_LT(std::abs(b.overRhoOwn), kOvershoot) << c.name << " " << n;  // the air behind its shock
      } else {
        EXPECT_LT(b.overRho, kOvershoot) << c.name << " " << n;
      }
    }
}

// The Lagrangian phase's energy correction (src/ice/sources/lagrangian_phase.cpp): a share a fluid
// cannot take without draining its thermal energy (a compressible fluid's small mass holding most
// of theta kappa, so most of a negative correction) goes to the fluids that took theirs, by heat
// capacity. Water against air with the default settings then creates no energy (the audit's
// share at 400 cells 8.6e-5 before, ~1e-23 after, round-off of the sums).
TEST(IceShockDefaults, WaterAirLagrangianSharesCreateNoEnergy) {
  for (const int n : {100, 400}) {
    const test::ShockResult r = test::runShockCase(test::waterAirRealDensity(), n, {});
    ASSERT_TRUE(r.completed) << n << ": " << r.error;
    std::printf("  %d cells: energy created by the fallbacks %.2e of the total\n", n, r.createdShare);
    EXPECT_LT(r.createdShare, 1e-15) << n;
  }
}

// The semi-implicit pressure with two fluids starts from the explicit step and grows 1.1 times a
// step (ice_constants.h, kSemiImplicitStepGrowth). Water against air at the real density ratio:
// first order then stays within 2 % behind the air shock at every resolution (it was +5.00 % in
// pressure at 400 cells, +3.96 % at 800) and the fallbacks create no energy (3.7e-4 of the total at
// 400 cells before); van Leer and superbee, which stopped at every resolution (air below 0 K at
// the contact, steps 17-45), complete and create no energy. Their air overshoots 2-6 % at 200 and
// 400 cells (docs/ice.md "The semi-implicit step's start"): completion is asserted, not the bound.
TEST(IceShockDefaults, SemiImplicitWaterAirStartsFromTheExplicitStep) {
  const test::ShockCase c = test::waterAirRealDensity();
  for (const char* setting : {"first_order", "van_leer", "superbee"})
    for (const int n : kCells) {
      test::TubeOptions o;
      o.pressure = "semi_implicit";
      if (std::string(setting) == "first_order") o.advection = "first_order";
      else o.limiter = setting;
      const test::ShockResult r = test::runShockCase(c, n, o);
      ASSERT_TRUE(r.completed) << setting << " " << n << ": " << r.error;
      std::printf("  %s %d cells: %ld steps, overshoot air rho %+.2f %%, p %+.2f %%; energy created %.2e\n", setting, n,
                  r.steps, r.overRhoOwn, r.overP, r.createdShare);
      EXPECT_LT(r.createdShare, 1e-15) << setting << " " << n;
      if (std::string(setting) == "first_order") {
        EXPECT_LT(r.overRhoOwn, kOvershoot) << n;
        EXPECT_LT(r.overP, kOvershoot) << n;
      }
    }
}
