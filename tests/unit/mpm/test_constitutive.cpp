// Constitutive models against hand-computed values; the registry; the solid EOS.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/material/constitutive_model.h"
#include "mpm/material/j2_plasticity.h"
#include "core/material/solid_bulk_eos.h"
#include "mpm/particles/particle_set.h"

using namespace mpmice;
using namespace mpmice::mpm;

namespace {
constexpr double E = 200e9, nu = 0.3;
const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu)), lam = K - 2 * G / 3;

core::ModelSpec spec(const std::string& type) {
  core::ModelSpec m;
  m.type = type;
  m.params = {{"youngs_modulus", E}, {"poissons_ratio", nu}, {"bulk_modulus", K}, {"shear_modulus", G},
              {"yield_stress", 250e6}, {"hardening_modulus", 1e9}, {"failure_strain", 0}};
  return m;
}

ParticleSet one() {
  ParticleSet p;
  p.addParticle({0, 0, 0}, {0, 0, 0}, 1.0, 1.0, {0.5, 0.5, 0.5}, 0, 300, 0);
  return p;
}

/// Applies velocity gradient L for n steps of dt (F and volume updated as the solver does).
void strain(const ConstitutiveModel& m, ParticleSet& p, const double L[9], double dt, int n) {
  for (int s = 0; s < n; ++s) {
    for (int k = 0; k < 9; ++k) p.L[k][0] = L[k];
    double Fn[9];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        double v = p.F[3 * a + b][0];
        for (int c = 0; c < 3; ++c) v += dt * L[3 * a + c] * p.F[3 * c + b][0];
        Fn[3 * a + b] = v;
      }
    for (int k = 0; k < 9; ++k) p.F[k][0] = Fn[k];
    m.updateStress(p, 0, 1, dt);
  }
}
}  // namespace

TEST(LinearElastic, UniaxialStrain) {
  auto m = createConstitutiveModel(spec("linear_elastic"), "test");
  auto p = one();
  const double d = 1e-3, L[9] = {d, 0, 0, 0, 0, 0, 0, 0, 0};
  strain(*m, p, L, 1.0, 1);
  EXPECT_NEAR(p.stress[kXX][0], (lam + 2 * G) * d, 1e-6 * G * d);
  EXPECT_NEAR(p.stress[kYY][0], lam * d, 1e-6 * G * d);
  EXPECT_NEAR(p.stress[kZZ][0], lam * d, 1e-6 * G * d);
  EXPECT_NEAR(p.stress[kXY][0], 0, 1e-9);
}

TEST(LinearElastic, SimpleShear) {
  auto m = createConstitutiveModel(spec("linear_elastic"), "test");
  auto p = one();
  const double g = 1e-4, L[9] = {0, g, 0, 0, 0, 0, 0, 0, 0};
  strain(*m, p, L, 1.0, 1);
  EXPECT_NEAR(p.stress[kXY][0], G * g, 1e-9 * G * g);
  EXPECT_NEAR(p.stress[kXX][0], 0, 1e-9 * G * g);
  // Second step: the Jaumann spin rotates the shear stress into normal stresses (W s - s W).
  strain(*m, p, L, 1.0, 1);
  EXPECT_NEAR(p.stress[kXY][0], 2 * G * g, 1e-6 * G * g);
  EXPECT_NEAR(p.stress[kXX][0], G * g * g, 1e-6 * G * g * g);
  EXPECT_NEAR(p.stress[kYY][0], -G * g * g, 1e-6 * G * g * g);
}

TEST(NeoHookean, UniaxialStretch) {
  auto m = createConstitutiveModel(spec("neo_hookean"), "test");
  auto p = one();
  const double e = 0.2, L[9] = {e, 0, 0, 0, 0, 0, 0, 0, 0};
  strain(*m, p, L, 1.0, 1);  // F = diag(1.2, 1, 1)
  const double J = 1 + e;
  EXPECT_NEAR(p.stress[kXX][0], G / J * (J * J - 1) + lam * std::log(J) / J, 1e-9 * G);
  EXPECT_NEAR(p.stress[kYY][0], lam * std::log(J) / J, 1e-9 * G);
}

TEST(J2Plasticity, ReturnMappingHitsYieldSurface) {
  auto m = createConstitutiveModel(spec("j2_plasticity"), "test");
  auto p = one();
  const double d = 1e-4, L[9] = {d, 0, 0, 0, 0, 0, 0, 0, 0};
  strain(*m, p, L, 1.0, 40);  // uniaxial strain to 4e-3, well past yield
  const double s[6] = {p.stress[0][0], p.stress[1][0], p.stress[2][0], p.stress[3][0], p.stress[4][0], p.stress[5][0]};
  const double mean = (s[0] + s[1] + s[2]) / 3;
  const double dxx = s[0] - mean, dyy = s[1] - mean, dzz = s[2] - mean;
  const double q = std::sqrt(1.5 * (dxx * dxx + dyy * dyy + dzz * dzz));
  const double ep = p.eqps[0];
  EXPECT_GT(ep, 0);
  EXPECT_NEAR(q, 250e6 + 1e9 * ep, 1e-6 * 250e6);
  EXPECT_NEAR(mean, K * 4e-3, 1e-6 * K * 4e-3);  // pressure stays elastic
}

TEST(J2Plasticity, PiecewiseHardeningAndFailure) {
  J2Plasticity m({K, G}, 0, 0, 0.01, {0, 0.005, 0.02}, {250e6, 300e6, 330e6});
  double sy, h;
  m.yield(0.0025, sy, h);
  EXPECT_NEAR(sy, 275e6, 1);
  m.yield(0.01, sy, h);
  EXPECT_NEAR(sy, 310e6, 1);
  auto p = one();
  const double g = 2e-3, L[9] = {0, g, 0, 0, 0, 0, 0, 0, 0};
  strain(m, p, L, 1.0, 30);  // shear far past the failure strain
  EXPECT_EQ(p.failed[0], 1.0);
  EXPECT_NEAR(p.stress[kXY][0], 0.0, 1e-6);
}

TEST(ConstitutiveRegistry, UnknownNameListsChoices) {
  try {
    (void)createConstitutiveModel(spec("mooney_rivlin"), "materials.steel.constitutive");
    FAIL();
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("mooney_rivlin"), std::string::npos);
    EXPECT_NE(m.find("linear_elastic, neo_hookean, j2_plasticity"), std::string::npos) << m;
    EXPECT_NE(m.find("materials.steel"), std::string::npos) << m;
  }
}

TEST(SolidBulkEos, ContinuousAndInvertible) {
  const core::SolidBulkEos eos(117e9, 101325, 8900);
  EXPECT_NEAR(eos.pressure(8900), 101325, 1e-6);
  const double h = 1e-11;  // the tension branch is steep (exponent K / p_ref ~ 1e6) but smooth
  EXPECT_NEAR(eos.dpdrho(8900 * (1 - h)), eos.dpdrho(8900 * (1 + h)), 1e-3 * eos.dpdrho(8900));
  EXPECT_NEAR(eos.dpdrho(8900), 117e9 / 8900, 1e-6 * 117e9 / 8900);
  for (double p : {1e3, 5e4, 101325.0, 1e6, 1e9})
    EXPECT_NEAR(eos.pressure(eos.density(p)), p, 1e-8 * p + 1e-6);
  EXPECT_GT(eos.specificVolume(1.0), eos.specificVolume(1e5));  // tension branch -> larger v
  EXPECT_THROW(core::SolidBulkEos(0, 1, 1), std::invalid_argument);
}
