// Cavitation (docs/ice.md "Cavitation"): water pulled apart. A 1D periodic column of Mie-Gruneisen
// water at 1 bar, the left half moving at -v, the right half at +v (v = 100 m/s): two rarefactions
// leave the centre. The exact solution of the cut-off EOS (p = max(p_law, p_c)): each rarefaction
// follows the isentrope from (rho0, e0, -+v) down to p_c, where the velocity is u_c (the Riemann
// invariant u + int c / rho drho); for |u_c| > 0 the centre opens a cavity |x - 0.5| < |u_c| t of
// no liquid, at p = p_c. Asserted: the pressure never below p_c (without the model it falls to
// -1.4e8 Pa: the test can fail), the cavity's volume sum (1 - rho / rho_c) dx over the cavitated
// cells against 2 |u_c| t, mass, momentum and total energy to round-off (periodic: the halves
// collide at the seam, a shock pair that stays clear of the centre until t_end), no energy created
// by the fallbacks (round-off), every step healthy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "ice/eos/eos.h"
#include "ice/solver/health_check.h"
#include "ice_test_scenes.h"
#include "test_comm.h"

using namespace mpmice;

namespace {

constexpr double kV = 100.0, kP0 = 1e5, kRho0 = 1000.0, kT = 1.5e-4;

core::MaterialSpec water(bool cavitation, double pc) {
  core::MaterialSpec m;
  m.name = "water";
  m.eos = test::modelSpec("mie_gruneisen", {{"reference_density", 1000}, {"sound_speed", 1480}, {"slope", 1.92},
                                            {"gruneisen", 0.35}, {"reference_pressure", 1e5},
                                            {"reference_temperature", 300}});
  m.specific_heat = 4186;
  if (cavitation) m.cavitation = test::modelSpec("pressure_cutoff", {{"pressure", pc}});
  return m;
}

core::Scene pulledApart(int n, bool cavitation, double pc) {
  core::Scene s;
  s.name = "water_pulled_apart";
  s.mesh = core::Mesh(1, {0, 0, 0}, {1.0 / n, 1, 1}, {n, 1, 1});
  s.boundary[0].type = s.boundary[1].type = core::BoundaryType::Periodic;
  s.time.end = kT;
  s.materials = {water(cavitation, pc)};
  s.geometry = {test::region("left", test::box({0, 0, 0}, {1, 1, 1}), {{"water", 1.0}}, kP0, kRho0, {-kV, 0, 0}),
                test::region("right", test::box({0.5, -1, -1}, {2, 2, 2}), {{"water", 1.0}}, kP0, kRho0, {kV, 0, 0})};
  s.ice.advection = "second_order";
  return s;
}

// The left rarefaction's tail on the cut-off: integrates de/drho = p / rho^2, du/drho = -c / rho
// (RK4 in rho) from (rho0, e0, -v) down to p = p_c; returns u_c (and rho_c).
double cutoffVelocity(const ice::Eos& eos, double pc, double* rhoC) {
  double rho = kRho0, e = eos.internalEnergy(kRho0, kP0), u = -kV;
  const double h = -1e-4;  // drho [kg/m^3]
  auto rhs = [&](double r, double ee, double* de, double* du) {
    const double p = eos.pressure(r, ee);
    *de = p / (r * r);
    *du = -std::sqrt(eos.soundSpeed2(r, ee)) / r;
  };
  for (int it = 0; it < 10000000; ++it) {
    if (eos.pressure(rho, e) <= pc) break;
    double k1e, k1u, k2e, k2u, k3e, k3u, k4e, k4u;
    rhs(rho, e, &k1e, &k1u);
    rhs(rho + 0.5 * h, e + 0.5 * h * k1e, &k2e, &k2u);
    rhs(rho + 0.5 * h, e + 0.5 * h * k2e, &k3e, &k3u);
    rhs(rho + h, e + h * k3e, &k4e, &k4u);
    e += h * (k1e + 2 * k2e + 2 * k3e + k4e) / 6;
    u += h * (k1u + 2 * k2u + 2 * k3u + k4u) / 6;
    rho += h;
  }
  *rhoC = rho;
  return u;
}

struct Result {
  double pMin = 0, cavity = 0, dMass = 0, dMom = 0, dEnergy = 0, created = 0;
  long steps = 0;
  std::string health;
};

Result run(int n, bool cavitation, double pc) {
  ice::IceSolver sol(pulledApart(n, cavitation, pc), test::comm());
  const ice::Totals t0 = sol.totals();
  Result r;
  r.pMin = std::numeric_limits<double>::infinity();
  while (sol.time() < kT * (1 - 1e-12)) {
    sol.step();
    if (r.health.empty()) r.health = ice::findViolation(sol);
    core::forEach(sol.ownedBox(), [&](int i, int j, int k) { r.pMin = std::min(r.pMin, sol.pressure()(i, j, k)); });
  }
  const ice::Totals t1 = sol.totals();
  r.steps = sol.steps();
  r.dMass = std::abs(t1.mass / t0.mass - 1);
  r.dMom = std::abs(t1.momentum[0]) / (t0.mass * kV);
  r.dEnergy = std::abs(t1.energy / t0.energy - 1);
  r.created = sol.energyAudit().created / t0.energy;
  // The cavity: the cells at the cut-off, each short of the law's density there by 1 - rho / rho_c.
  const ice::Eos& eos = *sol.state().mat[0].eos;
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
    if (!(sol.pressure()(i, j, k) <= pc)) return;
    const double rho = sol.density(0, i, j, k), rc = eos.density(pc, sol.state().mat[0].eint(i, j, k));
    r.cavity += (1.0 - rho / rc) * sol.mesh().dx(0);
  });
  return r;
}

}  // namespace

TEST(IceCavitation, WaterPulledApartOpensACavityAtTheCutoff) {
  const double pc = 0.0;
  const auto eos = ice::makeEos(water(false, 0).eos, 4186);
  double rhoC = 0;
  const double uC = cutoffVelocity(*eos, pc, &rhoC);
  const double exact = 2 * std::abs(uC) * kT;
  std::printf("  exact: u_c = %.4f m/s, rho_c = %.4f kg/m^3, cavity 2 |u_c| t = %.6e m\n", uC, rhoC, exact);
  ASSERT_LT(uC, 0.0);  // v exceeds what the water's tension down to p_c can stop: a cavity opens
  for (const int n : {200, 400, 800}) {
    const Result r = run(n, true, pc);
    std::printf("  %d cells, %ld steps: p_min %.6e Pa, cavity %.6e m (%+.2f %%), |dM/M| %.1e, |dP|/(M v) %.1e, "
                "|dE/E| %.1e, created %.1e\n",
                n, r.steps, r.pMin, r.cavity, 100 * (r.cavity / exact - 1), r.dMass, r.dMom, r.dEnergy, r.created);
    EXPECT_EQ(r.health, "") << n;
    EXPECT_GE(r.pMin, pc) << n;                           // never below the cut-off
    EXPECT_NEAR(r.cavity, exact, 2e-3 * exact) << n;      // the exact cavity (measured within 3e-4)
    EXPECT_LT(r.dMass, 1e-12) << n;
    EXPECT_LT(r.dMom, 1e-10) << n;
    EXPECT_LT(r.dEnergy, 1e-10) << n;                     // no energy created or lost
    EXPECT_LT(r.created, 1e-12) << n;                     // the fallbacks: round-off (6.6e-14 at 800)
  }
}

// A tensile limit (p_c < 0): the same cavity bound, and the tension does work on the separating
// halves (their internal energy rises; the total stays).
TEST(IceCavitation, TensileLimitHoldsAndConservesEnergy) {
  const double pc = -1e6;
  const auto eos = ice::makeEos(water(false, 0).eos, 4186);
  double rhoC = 0;
  const double uC = cutoffVelocity(*eos, pc, &rhoC);
  const double exact = 2 * std::abs(uC) * kT;
  const Result r = run(400, true, pc);
  std::printf("  p_c = %.1e: u_c = %.4f m/s; 400 cells: p_min %.6e Pa, cavity %.6e m (exact %.6e, %+.2f %%), |dE/E| %.1e\n",
              pc, uC, r.pMin, r.cavity, exact, 100 * (r.cavity / exact - 1), r.dEnergy);
  EXPECT_EQ(r.health, "");
  EXPECT_GE(r.pMin, pc);
  EXPECT_NEAR(r.cavity, exact, 2e-3 * exact);  // p_c = 0 would give +0.7 %
  EXPECT_LT(r.dEnergy, 1e-10);
}

// Without the model the same water goes into tension of ~ rho c v: the bound above can fail.
TEST(IceCavitation, WithoutTheModelTheWaterGoesIntoTension) {
  const Result r = run(400, false, 0.0);
  std::printf("  no cavitation model, 400 cells: p_min %.4e Pa\n", r.pMin);
  EXPECT_LT(r.pMin, -1e7);
}
