// Equilibrium pressure for two and three materials against independent solutions; the pointwise
// exchange at K = 0, 1e15 and with absent materials.
#include <gtest/gtest.h>

#include <cmath>

#include "ice/eos/eos.h"
#include "ice/exchange/pointwise_exchange.h"
#include "ice/pressure/equilibrium_pressure.h"

using namespace mpmice;

namespace {
core::ModelSpec spec(const std::string& type, std::map<std::string, double> params) {
  core::ModelSpec s;
  s.type = type;
  s.params = std::move(params);
  return s;
}
}  // namespace

TEST(IceEquilibrium, TwoIdealGasesHaveAClosedForm) {
  // sum_r rho_r (g_r - 1) e_r / p = 1  =>  p = sum_r rho_r (g_r - 1) e_r.
  const auto a = ice::makeEos(spec("ideal_gas", {{"gamma", 1.4}}), 717);
  const auto b = ice::makeEos(spec("ideal_gas", {{"gamma", 1.67}}), 3000);
  ice::EquilibriumPressure eq({a.get(), b.get()}, 1e-12, 100);
  std::vector<double> ra = {0.3, 0.0, 1.0}, rb = {0.5, 2.0, 1e-9}, ea = {2e5, 2e5, 3e5}, eb = {1e5, 4e5, 1e6};
  std::vector<double> p = {1e5, 1e5, 1e5}, ma(3), mb(3);
  std::vector<int> it(3);
  const auto fails = eq.solve({0, 1, 2}, {ra.data(), rb.data()}, {ea.data(), eb.data()}, p.data(),
                              {ma.data(), mb.data()}, it.data());
  ASSERT_TRUE(fails.empty());
  for (int c = 0; c < 3; ++c) {
    const double exact = ra[c] * 0.4 * ea[c] + rb[c] * 0.67 * eb[c];
    EXPECT_NEAR(p[c], exact, 1e-12 * exact);
    EXPECT_NEAR(ra[c] / ma[c] * (ra[c] > 0) + rb[c] / mb[c], 1.0, 1e-12);
    EXPECT_LE(it[c], 30);
  }
}

TEST(IceEquilibrium, ThreeMaterialsAgainstBisection) {
  const auto air = ice::makeEos(spec("ideal_gas", {{"gamma", 1.4}}), 717);
  const auto water = ice::makeEos(spec("stiffened_gas", {{"gamma", 4.4}, {"p_inf", 6e8}}), 4186);
  const auto steel = ice::makeEos(spec("solid_bulk", {{"bulk_modulus", 117e9}, {"threshold_pressure", 101325},
                                                      {"reference_density", 8900}}), 450);
  const std::vector<const ice::Eos*> eos = {air.get(), water.get(), steel.get()};
  const double rho[3] = {0.6, 400.0, 2000.0}, e[3] = {2.5e5, 1.07e6, 1.35e5};
  auto f = [&](double p) {
    double s = 0;
    for (int r = 0; r < 3; ++r) s += rho[r] / eos[r]->density(p, e[r]);
    return 1.0 - s;
  };
  double lo = 1e3, hi = 1e10;  // independent reference: plain bisection
  for (int it = 0; it < 200; ++it) (f(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  ice::EquilibriumPressure eq(eos, 1e-12, 100);
  std::vector<double> p = {1e5}, m0(1), m1(1), m2(1);
  std::vector<int> it(1);
  const std::vector<double> r0 = {rho[0]}, r1 = {rho[1]}, r2 = {rho[2]}, e0 = {e[0]}, e1 = {e[1]}, e2 = {e[2]};
  const auto fails = eq.solve({0}, {r0.data(), r1.data(), r2.data()}, {e0.data(), e1.data(), e2.data()}, p.data(),
                              {m0.data(), m1.data(), m2.data()}, it.data());
  ASSERT_TRUE(fails.empty());
  EXPECT_NEAR(p[0], 0.5 * (lo + hi), 1e-9 * p[0]);
  EXPECT_GT(it[0], 0);
}

TEST(IceEquilibrium, FailureIsReportedNotHidden) {
  const auto a = ice::makeEos(spec("ideal_gas", {{"gamma", 1.4}}), 717);
  const auto b = ice::makeEos(spec("ideal_gas", {{"gamma", 1.4}}), 717);
  ice::EquilibriumPressure eq({a.get(), b.get()}, 1e-12, 5);
  std::vector<double> ra = {1.0}, rb = {1.0}, ea = {-1.0}, eb = {1e5}, p = {1e5}, ma(1), mb(1);
  std::vector<int> it(1);
  const auto fails = eq.solve({0}, {ra.data(), rb.data()}, {ea.data(), eb.data()}, p.data(), {ma.data(), mb.data()},
                              it.data());
  ASSERT_EQ(fails.size(), 1u);
  EXPECT_EQ(fails[0].cell, 0);
}

TEST(IceExchange, ZeroCouplingKeepsVelocities) {
  double s[2] = {1.0, 2.0}, w[4] = {0, 0, 0, 0}, x[2] = {3.0, -1.0};
  ice::pointwiseExchange(2, s, w, x, 1);
  EXPECT_EQ(x[0], 3.0);
  EXPECT_EQ(x[1], -1.0);
}

TEST(IceExchange, HugeCouplingGivesOneVelocityWithoutOvershoot) {
  for (const double W : {1e3, 1e9, 1e15, 1e25}) {
    double s[3] = {1.0, 1e-3, 50.0};
    const double x0[3] = {100.0, -7.0, 2.0};
    double w[9] = {0, W, W, W, 0, W, W, W, 0}, x[3] = {x0[0], x0[1], x0[2]};
    const double P = s[0] * x0[0] + s[1] * x0[1] + s[2] * x0[2], M = s[0] + s[1] + s[2];
    ice::pointwiseExchange(3, s, w, x, 1);
    const double sNew = 1.0 * x[0] + 1e-3 * x[1] + 50.0 * x[2];
    EXPECT_NEAR(sNew, P, 1e-13 * std::abs(P));
    for (int r = 0; r < 3; ++r) {
      EXPECT_LE(x[r], 100.0);
      EXPECT_GE(x[r], -7.0);
      if (W >= 1e9) {
        EXPECT_NEAR(x[r], P / M, 1e-6 * std::abs(P / M)) << W;
      }
    }
  }
}

TEST(IceExchange, AbsentMaterialIsDecoupled) {
  double s[3] = {2.0, 0.0, 1.0}, w[9] = {0, 0, 1e20, 0, 0, 0, 1e20, 0, 0};
  double x[3] = {1.0, 55.0, 4.0};
  ice::pointwiseExchange(3, s, w, x, 1);
  EXPECT_EQ(x[1], 55.0);
  EXPECT_NEAR(x[0], 2.0, 1e-12);
  EXPECT_NEAR(x[2], 2.0, 1e-12);
  EXPECT_TRUE(std::isfinite(x[0]));
}
