// ICE with its default settings (second order, van Leer, explicit, face_pressure: riemann) on Sod
// and Toro's tests 1-5 at 100, 200 and 400 cells (the cheap part of the sweep; the full sweep over
// every setting and 100..1600 cells is scripts/ice_shock_sweep.sh, docs/ice.md "Shocks"): every
// run completes through the health check, the overshoot behind each shock (% of the jump) and the
// stationary contact's velocity stay within the measured bounds, and L1(rho) falls with refinement.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "ice_shock_cases.h"

using namespace mpmice;

namespace {
const int kCells[3] = {100, 200, 400};
// Measured bounds where the 2 % target is not met (docs/ice.md "Shocks"; measured + ~10 %):
// test 5's slow shock at 100 / 200 / 400 cells +8.9 / +4.3 / +8.4 % (rho), +10.7 / +5.1 / +9.8 % (p);
// test 3 at 100 and 200 cells +3.27 % and +2.83 % (rho), at 400 cells +0.29 %.
constexpr double kToro5Overshoot = 12.0;
constexpr double kToro3OvershootCoarse = 3.6;
// Test 5's stationary contact |u - u*| / wave speed: 3.4e-3, 1.6e-3, 1.1e-5 at 100, 200, 400 cells.
constexpr double kToro5ContactCoarse = 4e-3;
}  // namespace

TEST(IceShockDefaults, ToroSuiteCompletesWithoutOvershootBehindTheShocks) {
  for (const test::ShockCase& c : test::toroCases()) {
    std::vector<double> err;
    for (const int n : kCells) {
      const test::ShockResult r = test::runShockCase(c, n, {});
      ASSERT_TRUE(r.completed) << c.name << " " << n << ": " << r.error;
      std::printf("  %s %d cells: L1(rho) %.4e, overshoot rho %+.2f %% p %+.2f %%, contact |u - u*| %.1e of the wave speed\n",
                  c.name.c_str(), n, r.l1, r.overRho, r.overP, r.contactU);
      // Test 5's slow shock (Mach 166, 0.78 m/s) keeps a two-cell ripple: bound at its measured
      // level (docs/ice.md "Shocks": the 2 % target is not met there); every other shock < 2 %.
      const double bound = c.name == "toro5" ? kToro5Overshoot : (c.name == "toro3" && n < 400 ? kToro3OvershootCoarse : 2.0);
      EXPECT_LT(r.overRho, bound) << c.name << " " << n;
      EXPECT_LT(r.overP, bound) << c.name << " " << n;
      if (c.name == "toro5") {
        EXPECT_LT(r.contactU, n < 400 ? kToro5ContactCoarse : 1e-3) << n;  // the stationary contact
      }
      EXPECT_GT(r.minP, 0.0) << c.name << " " << n;
      err.push_back(r.l1);
    }
    for (std::size_t i = 1; i < err.size(); ++i) EXPECT_LT(err[i], err[i - 1]) << c.name;
  }
}
