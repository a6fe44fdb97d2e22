// Each EOS: p(rho, e) and its inverse, the sound speed against a finite-difference isentrope, and
// d rho / d p at fixed e against finite differences; the registry's errors.
#include <gtest/gtest.h>

#include <cmath>

#include "ice/eos/eos.h"

using namespace mpmice;

namespace {

core::ModelSpec spec(const std::string& type, std::map<std::string, double> params) {
  core::ModelSpec s;
  s.type = type;
  s.params = std::move(params);
  return s;
}

core::ModelSpec foam() {
  return spec("crush_curve", {{"bulk_modulus", 1e8 / (3 * (1 - 2 * 0.05))}, {"threshold_pressure", 101325},
                              {"reference_density", 270}, {"plateau_stress", 1.5e6}, {"densification_strain", 2.30},
                              {"plastic_poissons_ratio", 0}, {"hardening_gamma", 2e6}, {"hardening_alpha2", 4e6},
                              {"hardening_beta", 2}, {"densified_bulk_modulus", 7.6e10}});
}

struct Case {
  core::ModelSpec spec;
  double rho, e;
};

std::vector<Case> cases() {
  return {
      {spec("ideal_gas", {{"gamma", 1.4}}), 1.2, 2.1e5},
      {spec("stiffened_gas", {{"gamma", 4.4}, {"p_inf", 6e8}}), 1000.0, 1.07e6},
      {spec("mie_gruneisen", {{"reference_density", 998}, {"sound_speed", 1483}, {"slope", 1.75},
                              {"gruneisen", 0.28}, {"reference_pressure", 1e5}}),
       1050.0, 2e4},
      {spec("mie_gruneisen", {{"reference_density", 998}, {"sound_speed", 1483}, {"slope", 1.75},
                              {"gruneisen", 0.28}, {"reference_pressure", 1e5}}),
       990.0, 1e3},
      {spec("jwl", {{"A", 371.2e9}, {"B", 3.231e9}, {"R1", 4.15}, {"R2", 0.95}, {"omega", 0.3},
                    {"reference_density", 1630}}),
       1630.0, 7.0e9 / 1630.0},
      {spec("jwl", {{"A", 371.2e9}, {"B", 3.231e9}, {"R1", 4.15}, {"R2", 0.95}, {"omega", 0.3},
                    {"reference_density", 1630}}),
       200.0, 2e6},
      {spec("solid_bulk", {{"bulk_modulus", 117e9}, {"threshold_pressure", 101325}, {"reference_density", 8900}}),
       8950.0, 3e5},
      // The underwater scenes' foam: tension, elastic, crushing (V/V0 0.5), compacted (past 0.1).
      {foam(), 265.0, 2e5},
      {foam(), 271.0, 2e5},
      {foam(), 540.0, 2e5},
      {foam(), 2800.0, 2e5},
  };
}

bool barotropic(const core::ModelSpec& s) { return s.type == "solid_bulk" || s.type == "crush_curve"; }

}  // namespace

TEST(IceEos, PressureAndInverse) {
  for (const Case& c : cases()) {
    const auto eos = ice::makeEos(c.spec, 716.0);
    const double p = eos->pressure(c.rho, c.e);
    EXPECT_NEAR(eos->density(p, c.e), c.rho, 1e-10 * c.rho) << c.spec.type;
    if (!barotropic(c.spec)) {
      EXPECT_NEAR(eos->internalEnergy(c.rho, p), c.e, 1e-8 * std::abs(c.e)) << c.spec.type;
    }
  }
}

TEST(IceEos, HandValues) {
  const auto ig = ice::makeEos(spec("ideal_gas", {{"gamma", 1.4}}), 717.5);
  EXPECT_DOUBLE_EQ(ig->pressure(1.0, 2.5), 1.0);
  EXPECT_NEAR(ig->soundSpeed2(1.0, 2.5), 1.4, 1e-14);
  const auto sg = ice::makeEos(spec("stiffened_gas", {{"gamma", 4.4}, {"p_inf", 6e8}}), 4186);
  EXPECT_NEAR(sg->pressure(1000.0, sg->internalEnergy(1000.0, 1e9)), 1e9, 1e-3);
  EXPECT_NEAR(sg->soundSpeed2(1000.0, sg->internalEnergy(1000.0, 1e9)), 4.4 * 1.6e9 / 1000.0, 1e-6);
  // Temperature round trip (stiffened gas: e = cv T + p_inf / rho).
  EXPECT_NEAR(sg->temperature(1000.0, sg->energyFromTemperature(1000.0, 300.0)), 300.0, 1e-9);
  EXPECT_NEAR(ig->densityFromPT(101325.0, 300.0), 101325.0 / (0.4 * 717.5 * 300.0), 1e-12);
}

TEST(IceEos, SoundSpeedIsTheIsentropicSlope) {
  for (const Case& c : cases()) {
    const auto eos = ice::makeEos(c.spec, 716.0);
    const double p = eos->pressure(c.rho, c.e);
    const double h = 1e-5 * c.rho;
    // Along an isentrope de = p / rho^2 drho (for solid_bulk p depends on rho only).
    const double pp = eos->pressure(c.rho + h, c.e + p / (c.rho * c.rho) * h);
    const double pm = eos->pressure(c.rho - h, c.e - p / (c.rho * c.rho) * h);
    const double c2 = eos->soundSpeed2(c.rho, c.e);
    const double fd = barotropic(c.spec) ? (eos->pressure(c.rho + h, c.e) - eos->pressure(c.rho - h, c.e)) / (2 * h)
                                         : (pp - pm) / (2 * h);
    EXPECT_NEAR(c2, fd, 1e-5 * std::abs(c2)) << c.spec.type;
    EXPECT_GT(c2, 0) << c.spec.type;
  }
}

TEST(IceEos, DensityDerivativeAtFixedEnergy) {
  for (const Case& c : cases()) {
    const auto eos = ice::makeEos(c.spec, 716.0);
    const double p = eos->pressure(c.rho, c.e);
    double rho, drdp;
    eos->density(1, &p, &c.e, &rho, &drdp);
    const double h = 1e-6 * std::max(std::abs(p), 1e5);
    const double fd = (eos->density(p + h, c.e) - eos->density(p - h, c.e)) / (2 * h);
    EXPECT_NEAR(drdp, fd, 1e-5 * std::abs(drdp)) << c.spec.type;
    // dv/dp = -drho/dp / rho^2 < 0
    EXPECT_LT(-drdp / (rho * rho), 0) << c.spec.type;
  }
}

TEST(IceEos, UnknownNameListsTheValidOnes) {
  try {
    (void)ice::makeEos(spec("ideal_gass", {{"gamma", 1.4}}), 716.0);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("ideal_gass"), std::string::npos);
    for (const auto& n : ice::eosNames()) EXPECT_NE(m.find(n), std::string::npos) << m;
  }
}

TEST(IceEos, MissingAndBadParameters) {
  EXPECT_THROW((void)ice::makeEos(spec("stiffened_gas", {{"gamma", 4.4}}), 716.0), std::invalid_argument);
  EXPECT_THROW((void)ice::makeEos(spec("ideal_gas", {{"gamma", 0.9}}), 716.0), std::invalid_argument);
  EXPECT_THROW((void)ice::makeEos(spec("ideal_gas", {{"gamma", 1.4}}), -1.0), std::invalid_argument);
}

// Mie-Gruneisen's reference state (rho0, p0) has e = 0; `reference_temperature` T0 puts it at T0
// (T = T0 + e / cv) instead of 0 K, where the health check stopped a water started at rho0, p0
// at the first round-off (configs/underwater_foam_2d.yaml). The pressure law is unchanged.
TEST(IceEos, MieGruneisenReferenceTemperature) {
  std::map<std::string, double> water{{"reference_density", 1000}, {"sound_speed", 1480}, {"slope", 1.92},
                                      {"gruneisen", 0.35}, {"reference_pressure", 1e5}};
  const auto cold = ice::makeEos(spec("mie_gruneisen", water), 4186.0);
  water["reference_temperature"] = 300.0;
  const auto warm = ice::makeEos(spec("mie_gruneisen", water), 4186.0);
  const double e0 = warm->internalEnergy(1000.0, 1e5);
  EXPECT_NEAR(e0, 0.0, 1e-6);
  EXPECT_NEAR(cold->temperature(1000.0, e0), 0.0, 1e-9);
  EXPECT_NEAR(warm->temperature(1000.0, e0), 300.0, 1e-9);
  EXPECT_NEAR(warm->densityFromPT(1e5, 300.0), 1000.0, 1e-9);
  EXPECT_NEAR(warm->temperature(1000.0, warm->energyFromTemperature(1000.0, 350.0)), 350.0, 1e-9);
  EXPECT_DOUBLE_EQ(warm->pressure(1050.0, 2e4), cold->pressure(1050.0, 2e4));
}
