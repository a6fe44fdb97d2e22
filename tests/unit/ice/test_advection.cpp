// Advection fluxes conserve: a periodic 3D box with three materials in random states (first and
// second order, every limiter) keeps mass, momentum and total energy to round-off; limiters give
// zero slopes at extrema and for constant data.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../../verification/ice/ice_test_scenes.h"
#include "ice/advection/limiter.h"
#include "test_comm.h"

using namespace mpmice;

TEST(IceLimiter, ZeroAtExtremaAndForConstants) {
  for (auto l : {ice::Limiter::Minmod, ice::Limiter::VanLeer, ice::Limiter::Superbee}) {
    EXPECT_EQ(ice::limitedSlope(l, 0.0, 0.0), 0.0);
    EXPECT_EQ(ice::limitedSlope(l, 1.0, -2.0), 0.0);
    EXPECT_NEAR(ice::limitedSlope(l, 1.0, 1.0), 1.0, 1e-15);
  }
  EXPECT_EQ(ice::limitedSlope(ice::Limiter::Minmod, 1.0, 3.0), 1.0);
  EXPECT_NEAR(ice::limitedSlope(ice::Limiter::VanLeer, 1.0, 3.0), 1.5, 1e-15);
  EXPECT_EQ(ice::limitedSlope(ice::Limiter::Superbee, 1.0, 3.0), 2.0);
}

TEST(IceAdvection, FluxesConserveIn3DWithThreeMaterials) {
  for (const std::string adv : {"first_order", "second_order"})
    for (const std::string lim : {"minmod", "van_leer", "superbee"}) {
      core::Scene s;
      s.name = "box3";
      s.mesh = core::Mesh(3, {0, 0, 0}, {0.1, 0.1, 0.1}, {6, 5, 4});
      for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
      s.materials = {test::idealGas("a"), test::idealGas("b", 1.67, 3000), test::stiffenedGas("c", 4.4, 6e8)};
      s.geometry = {test::region("all", test::box({0, 0, 0}, {1, 1, 1}), {{"a", 0.4}, {"b", 0.3}, {"c", 0.3}}, 1e5, 1.0)};
      s.geometry[0].density.reset();
      s.ice.advection = adv;
      s.ice.limiter = lim;
      s.ice.exchange_momentum = 1e4;
      ice::IceSolver sol(s, test::comm());
      const double V = sol.mesh().cellVolume();
      core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
        std::mt19937 gen(static_cast<unsigned>(7 + i + 100 * j + 10000 * k));
        std::uniform_real_distribution<double> U(0.0, 1.0);
        for (int r = 0; r < 3; ++r) {
          auto& m = sol.state().mat[r];
          m.mass(i, j, k) *= 0.5 + U(gen);
          for (int d = 0; d < 3; ++d) m.vel(i, j, k, d) = 20 * (2 * U(gen) - 1);
        }
        (void)V;
      });
      sol.computeEquilibriumPressure();
      const ice::Totals t0 = sol.totals();
      for (int n = 0; n < 20; ++n) sol.step();
      const ice::Totals t1 = sol.totals();
      EXPECT_NEAR(t1.mass, t0.mass, 1e-13 * t0.mass) << adv << " " << lim;
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(t1.momentum[d], t0.momentum[d], 1e-13 * t0.mass * 20) << adv << " " << lim;
      EXPECT_NEAR(t1.energy, t0.energy, 1e-13 * t0.energy) << adv << " " << lim;
    }
}
