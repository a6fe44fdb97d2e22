// Sod's shock tube against the exact Riemann solution: L1 density error at four resolutions and
// the observed order, for first and second order advection, explicit and semi-implicit pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ice_test_scenes.h"
#include "test_comm.h"

using namespace mpmice;
using test::Primitive;

namespace {

struct Study {
  double err[4];
  double order;  // least-squares slope over the four grids
};

Study sodStudy(const test::TubeOptions& o) {
  const Primitive L{1, 0, 1}, R{0.125, 0, 0.1};
  const test::ExactRiemann ex(L, R);
  const int ns[4] = {100, 200, 400, 800};
  Study st{};
  for (int q = 0; q < 4; ++q) {
    const core::Scene sc = test::shockTube(ns[q], L, R, 0.5, 0.2, o);
    ice::IceSolver s(sc, test::comm());
    test::runToEnd(s, 0.2);
    st.err[q] = test::l1Density(s, [&](double x) { return ex.sample((x - 0.5) / 0.2).rho; });
  }
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int q = 0; q < 4; ++q) {
    const double x = std::log(1.0 / ns[q]), y = std::log(st.err[q]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  st.order = (4 * sxy - sx * sy) / (4 * sxx - sx * sx);
  std::printf("  %s %s: L1 = %.3e %.3e %.3e %.3e, order %.2f\n", o.advection.c_str(), o.pressure.c_str(), st.err[0],
              st.err[1], st.err[2], st.err[3], st.order);
  return st;
}

}  // namespace

TEST(IceSod, ExactRiemannStarState) {
  const test::ExactRiemann ex({1, 0, 1}, {0.125, 0, 0.1});
  EXPECT_NEAR(ex.pStar(), 0.30313, 1e-5);
  EXPECT_NEAR(ex.uStar(), 0.92745, 1e-5);
  EXPECT_NEAR(ex.rhoStar(-1), 0.42632, 1e-5);
  EXPECT_NEAR(ex.rhoStar(+1), 0.26557, 1e-5);
  EXPECT_NEAR(ex.shockSpeed(+1), 1.7522, 1e-4);
}

TEST(IceSod, FirstOrderExplicit) {
  const Study s = sodStudy({"first_order", "explicit"});
  EXPECT_LT(s.err[0], 2.0e-2);  // measured 1.69e-2 -> 4.30e-3, order 0.66
  EXPECT_LT(s.err[3], 5.0e-3);
  EXPECT_GT(s.order, 0.6);
}

TEST(IceSod, SecondOrderExplicit) {
  const Study s = sodStudy({"second_order", "explicit"});
  EXPECT_LT(s.err[0], 1.3e-2);  // measured 1.14e-2 -> 2.08e-3, order 0.82
  EXPECT_LT(s.err[3], 2.5e-3);
  EXPECT_GT(s.order, 0.75);
}

TEST(IceSod, FirstOrderSemiImplicit) {
  const Study s = sodStudy({"first_order", "semi_implicit"});
  // measured 2.13e-2 -> 5.19e-3, order 0.68 (convective CFL). Before the semi-implicit step took
  // the pressure jump's speed (docs/ice.md "Shocks", semi-implicit start) the first step ran at an
  // acoustic CFL number of ~3: 2.93e-2 -> 5.90e-3, order 0.77, that order raised by the start-up
  // error at 100 cells; the order bound is now first order explicit's, the error bounds tighter.
  EXPECT_LT(s.err[0], 2.4e-2);
  EXPECT_LT(s.err[3], 5.8e-3);
  EXPECT_GT(s.order, 0.6);
}

TEST(IceSod, SecondOrderSemiImplicit) {
  const Study s = sodStudy({"second_order", "semi_implicit"});
  // measured 1.69e-2 -> 3.39e-3, order 0.77; before the semi-implicit start fix 2.74e-2 -> 4.35e-3,
  // order 0.88, raised by the start-up error at 100 cells (+7.9 % behind the shock): the order
  // bound is now second order explicit's, the error bounds tighter.
  EXPECT_LT(s.err[0], 1.9e-2);
  EXPECT_LT(s.err[3], 3.8e-3);
  EXPECT_GT(s.order, 0.75);
}
