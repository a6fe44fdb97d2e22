// Toro's tests 1-5 (ch. 4, table 4.1) with the shock viscosity (ice.shock_viscosity: linear 1,
// quadratic 2) at 200, 400, 800 and 1600 cells: the overshoot behind the right shock of tests 4 (the
// shock pair) and 5 (a slow shock beside a stationary contact) in % of the jump, the stationary
// contact's velocity against the waves' speed, and L1(rho) against the exact solution with its
// fitted order. Without the viscosity (the default) test 4 overshoots by 13.6 % / 17.2 % (rho / p)
// and test 5 by 57 % / 64 %, with the contact at |u| 0.58 (400 cells): docs/ice.md "Shock viscosity".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "ice_test_scenes.h"
#include "test_comm.h"

using namespace mpmice;
using test::Primitive;

namespace {

struct Toro {
  const char* name;
  Primitive L, R;
  double x0, t;
};
const Toro kToro[5] = {{"test 1", {1, 0.75, 1}, {0.125, 0, 0.1}, 0.3, 0.2},
                       {"test 2 (123)", {1, -2, 0.4}, {1, 2, 0.4}, 0.5, 0.15},
                       {"test 3", {1, 0, 1000}, {1, 0, 0.01}, 0.5, 0.012},
                       {"test 4", {5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950}, 0.4, 0.035},
                       {"test 5", {1, -19.59745, 1000}, {1, -19.59745, 0.01}, 0.8, 0.012}};
const int kCells[4] = {200, 400, 800, 1600};

struct Result {
  double l1 = 0, overRho = 0, overP = 0, contactU = 0;
};

Result run(const Toro& c, int n) {
  core::Scene sc = test::shockTube(n, c.L, c.R, c.x0, c.t);
  sc.ice.shock_viscosity_linear = 1.0;
  sc.ice.shock_viscosity_quadratic = 2.0;
  // The viscosity alone, as measured (docs/ice.md). Stable with the default (riemann) too since its
  // bound is in the step, but both dissipations together smear more than the L1 bounds below allow
  // (test 4 at 200 cells 0.429 > 0.39, test 5 0.0522 > 0.05; overshoots then 0.0-0.3 %).
  sc.ice.face_pressure = "average";
  ice::IceSolver s(sc, test::comm());
  test::runToEnd(s, c.t);
  const test::ExactRiemann ex(c.L, c.R);
  Result r;
  r.l1 = test::l1Density(s, [&](double x) { return ex.sample((x - c.x0) / c.t).rho; });
  // Behind the right shock: from halfway between contact and shock to 5 cells past the shock.
  const double xs = c.x0 + ex.shockSpeed(+1) * c.t, xc = c.x0 + ex.uStar() * c.t, dx = 1.0 / n;
  const double rPost = ex.rhoStar(+1), pPost = ex.pStar();
  double mr = -1e300, mp = -1e300;
  core::forEach(s.ownedBox(), [&](int i, int j, int k) {
    const double x = s.mesh().cellCenter(0, i);
    if (x > 0.5 * (xc + xs) && x < xs + 5 * dx) {
      mr = std::max(mr, s.density(0, i, j, k));
      mp = std::max(mp, s.pressure()(i, j, k));
    }
    if (std::abs(x - xc) < 5 * dx) r.contactU = std::max(r.contactU, std::abs(s.state().mat[0].vel(i, j, k, 0) - ex.uStar()));
  });
  r.overRho = 100 * (mr - rPost) / (rPost - c.R.rho);
  r.overP = 100 * (mp - pPost) / (pPost - c.R.p);
  return r;
}

double fittedOrder(const std::vector<double>& err) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int m = static_cast<int>(err.size());
  for (int i = 0; i < m; ++i) {
    const double x = std::log(static_cast<double>(kCells[i])), y = std::log(err[static_cast<std::size_t>(i)]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace

TEST(IceToroShockViscosity, NoOvershootBehindTheShocksAndAStationaryContact) {
  for (int tc : {3, 4}) {  // tests 4 and 5: strong right shocks
    const Toro& c = kToro[tc];
    const test::ExactRiemann ex(c.L, c.R);
    const double waveSpeed = std::max(std::abs(ex.shockSpeed(+1)), std::abs(c.L.u) + std::sqrt(1.4 * c.L.p / c.L.rho));
    for (const int n : kCells) {
      const Result r = run(c, n);
      std::printf("  %s, %d cells: overshoot behind the right shock rho %+.2f %%, p %+.2f %% of the jump; contact |u - u*| %.2e (%.1e of the wave speed)\n",
                  c.name, n, r.overRho, r.overP, r.contactU, r.contactU / waveSpeed);
      EXPECT_LT(r.overRho, tc == 3 ? 2.0 : 2.5) << c.name << " " << n;  // measured <= 0.04 % (test 4), 1.97 % (test 5)
      EXPECT_LT(r.overP, tc == 3 ? 2.0 : 2.5) << c.name << " " << n;    // measured <= 0.01 % (test 4), 2.30 % (test 5)
      if (tc == 4) {
        EXPECT_LT(r.contactU, 1e-3 * waveSpeed) << n;  // the stationary contact
      }
    }
  }
}

TEST(IceToroShockViscosity, L1DensityAndFittedOrder) {
  // Bounds: measured errors + 10 %, orders - 0.1 (docs/ice.md "Shock viscosity").
  const double maxErr200[5] = {8.5e-3, 7.3e-3, 7.3e-2, 3.9e-1, 5.0e-2};
  const double minOrder[5] = {0.73, 0.99, 0.86, 0.79, 0.9};
  for (int tc = 0; tc < 5; ++tc) {
    std::vector<double> err;
    for (const int n : kCells) err.push_back(run(kToro[tc], n).l1);
    const double order = fittedOrder(err);
    std::printf("  %s: L1(rho) %.3e %.3e %.3e %.3e, fitted order %.2f\n", kToro[tc].name, err[0], err[1], err[2], err[3], order);
    EXPECT_LT(err[0], maxErr200[tc]) << kToro[tc].name;
    EXPECT_GT(order, minOrder[tc]) << kToro[tc].name;
    for (std::size_t i = 1; i < err.size(); ++i) EXPECT_LT(err[i], err[i - 1]) << kToro[tc].name;
  }
}
