// Conservation: a closed 2D box with random initial states of two materials in every cell keeps
// total mass, momentum and energy to 1e-12 relative over 1000 steps, for first and second order
// advection: periodic in both directions (all three totals), and with slip walls (mass and
// energy; the walls' pressure forces change the momentum). Exchange extremes: two materials at different velocities reach one
// velocity in one step without overshoot at K = 1e15, and stay independent at K = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "ice_test_scenes.h"
#include "test_comm.h"

using namespace mpmice;

namespace {

core::Scene twoGasBox(int nx, int ny, double K, const std::string& adv) {
  core::Scene s;
  s.name = "box";
  s.mesh = core::Mesh(2, {0, 0, 0}, {1.0 / nx, 1.0 / ny, 1}, {nx, ny, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::SlipWall;
  s.time.end = 1e30;
  s.time.cfl = 0.3;
  s.materials = {test::idealGas("a", 1.4), test::idealGas("b", 1.67, 3000)};
  s.geometry = {test::region("all", test::box({0, 0, 0}, {1, 1, 1}), {{"a", 0.5}, {"b", 0.5}}, 1e5, 1.0)};
  s.ice.exchange_momentum = K;
  s.ice.advection = adv;
  return s;
}

/// Random fractions, densities, energies and velocities in every cell (owned cells; the pressure
/// is then recomputed). The seed depends on the global cell index, so any decomposition agrees.
void randomize(ice::IceSolver& s, double uScale) {
  const double V = s.mesh().cellVolume();
  core::forEach(s.ownedBox(), [&](int i, int j, int k) {
    std::mt19937 gen(static_cast<unsigned>(1 + i + 1000 * j + 1000000 * k));
    std::uniform_real_distribution<double> U(0.0, 1.0);
    const double th = 0.1 + 0.8 * U(gen);
    for (int r = 0; r < 2; ++r) {
      auto& m = s.state().mat[r];
      const double rho = 0.8 + 0.4 * U(gen);
      m.mass(i, j, k) = (r == 0 ? th : 1 - th) * rho * V;
      m.eint(i, j, k) = 2.5e5 * (0.8 + 0.4 * U(gen));
      for (int d = 0; d < 2; ++d) m.vel(i, j, k, d) = uScale * (2 * U(gen) - 1);
    }
  });
  s.computeEquilibriumPressure();
}

}  // namespace

TEST(IceConservation, ClosedBox2DRandomStates1000Steps) {
  for (const char* adv : {"first_order", "second_order", "walls"}) {
    const bool walls = std::string(adv) == "walls";
    core::Scene sc = twoGasBox(16, 16, 1e3, walls ? "second_order" : adv);
    if (!walls)
      for (auto& b : sc.boundary) b.type = core::BoundaryType::Periodic;
    ice::IceSolver s(sc, test::comm());
    randomize(s, 50.0);
    const ice::Totals t0 = s.totals();
    for (int n = 0; n < 1000; ++n) s.step();
    const ice::Totals t1 = s.totals();
    const double pScale = t0.mass * 50.0;
    const double dm = std::abs(t1.mass - t0.mass) / t0.mass;
    const double dpx = std::abs(t1.momentum[0] - t0.momentum[0]) / pScale;
    const double dpy = std::abs(t1.momentum[1] - t0.momentum[1]) / pScale;
    const double de = std::abs(t1.energy - t0.energy) / t0.energy;
    std::printf("  %s: %ld steps to t = %.3e: mass %.1e, momentum %.1e %.1e, energy %.1e (relative)\n", adv,
                s.steps(), s.time(), dm, dpx, dpy, de);
    EXPECT_LT(dm, 1e-12);
    if (!walls) {
      EXPECT_LT(dpx, 1e-12);
      EXPECT_LT(dpy, 1e-12);
    }
    EXPECT_LT(de, 1e-12);
    EXPECT_EQ(s.energyFallbacks(), 0);
  }
}

TEST(IceExchange, InfiniteAndZeroCoefficients) {
  for (const double K : {1e15, 0.0}) {
    core::Scene sc = twoGasBox(4, 4, K, "second_order");
    for (auto& b : sc.boundary) b.type = core::BoundaryType::Periodic;
    ice::IceSolver s(sc, test::comm());
    core::forEach(s.ownedBox(), [&](int i, int j, int k) {
      s.state().mat[0].vel(i, j, k, 0) = 100.0;
      s.state().mat[1].vel(i, j, k, 0) = -20.0;
    });
    s.computeEquilibriumPressure();
    const double ma = s.state().mat[0].mass(0, 0, 0), mb = s.state().mat[1].mass(0, 0, 0);
    const double ucm = (ma * 100.0 - mb * 20.0) / (ma + mb);
    const ice::Totals t0 = s.totals();
    s.step();
    double maxDev = 0;
    core::forEach(s.ownedBox(), [&](int i, int j, int k) {
      const double ua = s.state().mat[0].vel(i, j, k, 0), ub = s.state().mat[1].vel(i, j, k, 0);
      if (K > 0) {
        maxDev = std::max({maxDev, std::abs(ua - ucm), std::abs(ub - ucm)});
        EXPECT_LE(ua, 100.0);
        EXPECT_GE(ub, -20.0);
      } else {
        maxDev = std::max({maxDev, std::abs(ua - 100.0), std::abs(ub + 20.0)});
      }
    });
    const ice::Totals t1 = s.totals();
    std::printf("  K = %g: max |u - expected| = %.2e m/s, energy change %.1e (relative)\n", K, maxDev,
                std::abs(t1.energy - t0.energy) / t0.energy);
    EXPECT_LT(maxDev, 1e-10 * 100.0);
    EXPECT_LT(std::abs(t1.energy - t0.energy) / t0.energy, 1e-14);
  }
}
