// A region of JWL detonation products at rest (10 GPa, 1630 kg/m^3) against water at rest (1 bar,
// 1000 kg/m^3; stiffened gas 4.4 / 6e8 and Mie-Gruneisen 1483 / 1.75 / 0.28), interface at x = 0.5,
// t = 60 us: the shock transmitted into the water (its pressure, the plateau between the contact
// and the shock, and its speed) against the exact Riemann solution of the same equations of state
// (riemann_general.h), within 2 %, at 400, 800 and 1600 cells (200 cells: the shock speed -2.05 %).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "ice/eos/eos.h"
#include "ice_test_scenes.h"
#include "riemann_general.h"
#include "test_comm.h"

using namespace mpmice;

namespace {

core::MaterialSpec jwlProducts(double A, double B, double R1, double R2, double omega, double rho0) {
  core::MaterialSpec m;
  m.name = "products";
  m.eos = test::modelSpec("jwl", {{"A", A}, {"B", B}, {"R1", R1}, {"R2", R2}, {"omega", omega}, {"reference_density", rho0}});
  m.specific_heat = 1000;
  return m;
}
// TNT's JWL (Dobratz's set: 1630 kg/m^3), the test's products.
core::MaterialSpec products() { return jwlProducts(371.2e9, 3.231e9, 4.15, 0.95, 0.3, 1630); }
// PETN's (1770 kg/m^3; the underwater scene's charge, configs/underwater_foam_2d.yaml).
core::MaterialSpec petnProducts() { return jwlProducts(617.0e9, 16.926e9, 4.4, 1.2, 0.25, 1770); }

core::MaterialSpec mgWater() {
  core::MaterialSpec m;
  m.name = "water";
  m.eos = test::modelSpec("mie_gruneisen", {{"reference_density", 1000}, {"sound_speed", 1483}, {"slope", 1.75},
                                            {"gruneisen", 0.28}, {"reference_pressure", 1e5}});
  m.specific_heat = 4186;
  return m;
}

// The products (gas, state L) at rest against the water at 1 bar, to t.
void transmittedShock(const core::MaterialSpec& water, const char* label, const core::MaterialSpec& gas = products(),
                      test::Primitive L = {1630, 0, 1e10}, double t = 60e-6) {
  const double x0 = 0.5;
  const test::Primitive R{1000, 0, 1e5};
  const auto eosL = ice::makeEos(gas.eos, gas.specific_heat);
  const auto eosR = ice::makeEos(water.eos, water.specific_heat);
  const test::GeneralRiemann ex(L, *eosL, R, *eosR, 1e3);
  const double pStar = ex.pStar(), S = ex.shockSpeed(+1), uStar = ex.uStar();
  std::printf("  %s: exact p* = %.4e Pa, u* = %.2f m/s, water shock %.1f m/s, rho* water %.2f\n", label, pStar, uStar,
              S, ex.rhoStar(+1));
  ASSERT_GT(pStar, R.p);
  ASSERT_LT(pStar, L.p);
  for (const int n : {400, 800, 1600}) {
    core::Scene s;
    s.name = "jwl_water";
    s.mesh = core::Mesh(1, {0, 0, 0}, {1.0 / n, 1, 1}, {n, 1, 1});
    for (auto& b : s.boundary) b.type = core::BoundaryType::Outflow;
    s.time.end = t;
    s.materials = {gas, water};
    s.geometry = {test::region("products", test::box({0, 0, 0}, {x0, 1, 1}), {{"products", 1.0}}, L.p, L.rho),
                  test::region("water", test::box({x0, -1, -1}, {2, 2, 2}), {{"water", 1.0}}, R.p, R.rho)};
    ice::IceSolver sol(s, test::comm());
    test::runToEnd(sol, t);
    const double dx = 1.0 / n, xc = x0 + uStar * t, xs = x0 + S * t;
    // Plateau: the median pressure of the water cells between the contact and the shock, 4 cells
    // clear of each. Shock: where a sharp jump from the plateau to p_R would hold the same
    // integral of p - p_R from the plateau's start on (sub-cell, whatever the profile's width).
    const double xa = xc + 4 * dx;
    std::vector<double> plateau;
    core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
      const double x = sol.mesh().cellCenter(0, i), p = sol.pressure()(i, j, k);
      if (x > xa && x < xs - 4 * dx) plateau.push_back(p);
    });
    ASSERT_FALSE(plateau.empty());
    std::nth_element(plateau.begin(), plateau.begin() + plateau.size() / 2, plateau.end());
    const double pNum = plateau[plateau.size() / 2];
    double integral = 0;
    core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
      const double x = sol.mesh().cellCenter(0, i);
      if (x - 0.5 * dx >= xa) integral += (sol.pressure()(i, j, k) - R.p) * dx;
    });
    const double shock = xa + integral / (pNum - R.p), sNum = (shock - x0) / t;
    std::printf("  %s, %d cells: %ld steps, water plateau p %.4e (exact %.4e, %+.2f %%), shock speed %.1f (exact %.1f, %+.2f %%)\n",
                label, n, sol.steps(), pNum, pStar, 100 * (pNum / pStar - 1), sNum, S, 100 * (sNum / S - 1));
    EXPECT_NEAR(pNum, pStar, 0.02 * pStar) << n;
    EXPECT_NEAR(sNum, S, 0.02 * S) << n;
  }
}

}  // namespace

TEST(IceJwlWater, TransmittedShockInStiffenedWater) { transmittedShock(test::stiffenedGas("water", 4.4, 6e8), "stiffened-gas water"); }
TEST(IceJwlWater, TransmittedShockInMieGruneisenWater) { transmittedShock(mgWater(), "Mie-Gruneisen water"); }

// A neighbour (7 Dec 2026): PETN's products at the underwater scene's 13.7 GPa and 1770 kg/m^3
// against Mie-Gruneisen water, to 40 us (the faster water shock stays on the mesh).
TEST(IceJwlWater, PetnProductsAtTheUnderwaterScenesStateInMieGruneisenWater) {
  transmittedShock(mgWater(), "PETN, Mie-Gruneisen water", petnProducts(), {1770, 0, 13.7e9}, 40e-6);
}

// The general solver against the closed-form one where both apply (stiffened gas | ideal gas).
TEST(IceJwlWater, GeneralExactSolverMatchesTheClosedFormOne) {
  const test::Primitive L{1000, 0, 1e9}, R{50, 0, 1e5};
  const auto w = ice::makeEos(test::modelSpec("stiffened_gas", {{"gamma", 4.4}, {"p_inf", 6e8}}), 4186);
  const auto a = ice::makeEos(test::modelSpec("ideal_gas", {{"gamma", 1.4}}), 717.5);
  const test::GeneralRiemann g(L, *w, R, *a, 1e3);
  const test::ExactRiemann c(L, R, {4.4, 6e8}, {1.4, 0});
  EXPECT_NEAR(g.pStar(), c.pStar(), 1e-6 * c.pStar());
  EXPECT_NEAR(g.uStar(), c.uStar(), 1e-6 * c.uStar());
  EXPECT_NEAR(g.shockSpeed(+1), c.shockSpeed(+1), 1e-6 * c.shockSpeed(+1));
  EXPECT_NEAR(g.rhoStar(-1), c.rhoStar(-1), 1e-6 * c.rhoStar(-1));
  // A left shock: the reverse problem.
  const test::GeneralRiemann g2(R, *a, L, *w, 1e3);
  const test::ExactRiemann c2(R, L, {1.4, 0}, {4.4, 6e8});
  EXPECT_NEAR(g2.pStar(), c2.pStar(), 1e-6 * c2.pStar());
  EXPECT_NEAR(g2.shockSpeed(-1), c2.shockSpeed(-1), 1e-6 * std::abs(c2.shockSpeed(-1)));
}
