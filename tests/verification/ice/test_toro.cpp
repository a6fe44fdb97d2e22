// Toro's tests 1-3 (ch. 4) on 400 cells: run to the end, stay positive, bound the L1 density error
// against the exact Riemann solution (measured at 400 cells: 4.06e-3, 3.11e-3, 2.48e-2).
#include <gtest/gtest.h>

#include <cstdio>

#include "ice_test_scenes.h"
#include "test_comm.h"

using namespace mpmice;
using test::Primitive;

namespace {

void toro(Primitive L, Primitive R, double x0, double tEnd, double bound, const char* name) {
  const test::ExactRiemann ex(L, R);
  const core::Scene sc = test::shockTube(400, L, R, x0, tEnd);
  ice::IceSolver s(sc, test::comm());
  test::runToEnd(s, tEnd);
  EXPECT_NEAR(s.time(), tEnd, 1e-12);
  double minP = 1e300, minRho = 1e300;
  core::forEach(s.ownedBox(), [&](int i, int j, int k) {
    minP = std::min(minP, s.pressure()(i, j, k));
    minRho = std::min(minRho, s.density(0, i, j, k));
  });
  EXPECT_GT(minP, 0.0);
  EXPECT_GT(minRho, 0.0);
  const double err = test::l1Density(s, [&](double x) { return ex.sample((x - x0) / tEnd).rho; });
  std::printf("  %s: %ld steps, L1(rho) = %.3e, min p = %.3e, min rho = %.3e\n", name, s.steps(), err, minP, minRho);
  EXPECT_LT(err, bound);
}

}  // namespace

TEST(IceToro, Test1) { toro({1, 0.75, 1}, {0.125, 0, 0.1}, 0.3, 0.2, 6.0e-3, "Toro 1"); }
TEST(IceToro, Test2Rarefactions) { toro({1, -2, 0.4}, {1, 2, 0.4}, 0.5, 0.15, 6.0e-3, "Toro 2"); }
TEST(IceToro, Test3StrongShock) { toro({1, 0, 1000}, {1, 0, 0.01}, 0.5, 0.012, 4.0e-2, "Toro 3"); }
