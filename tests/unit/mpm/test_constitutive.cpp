// Constitutive models against hand-computed values; the registry; the solid EOS.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "mpm/material/constitutive_model.h"
#include "mpm/material/crushable_foam.h"
#include "mpm/material/j2_plasticity.h"
#include "core/material/foam_crush_curve.h"
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
    p.vol[0] = p.vol0[0] * (Fn[0] * (Fn[4] * Fn[8] - Fn[5] * Fn[7]) - Fn[1] * (Fn[3] * Fn[8] - Fn[5] * Fn[6]) +
                            Fn[2] * (Fn[3] * Fn[7] - Fn[4] * Fn[6]));
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

// ---------------------------------------------------------------- the slides' models (issue 16)
namespace {

/// Drives one particle in uniaxial STRESS: axial rate d, the lateral rates found each step (secant
/// on a copy of the particle) so that sigma_yy = sigma_zz = 0 to 1e-9 of the axial stress.
/// Returns the axial strain sum d dt.
double uniaxialStress(const ConstitutiveModel& m, ParticleSet& p, double d, double dt, int n) {
  double lat = 0;
  for (int s = 0; s < n; ++s) {
    auto trial = [&](double l, ParticleSet& q) {
      q = p;
      const double L[9] = {d, 0, 0, 0, l, 0, 0, 0, l};
      strain(m, q, L, dt, 1);
      return q.stress[kYY][0];
    };
    ParticleSet q;
    double l0 = lat, r0 = trial(l0, q), l1 = lat - 0.1 * d - 1e-12, r1 = trial(l1, q);
    for (int it = 0; it < 60 && std::fabs(r1) > 1e-9 * std::fabs(q.stress[kXX][0]) + 1e-6; ++it) {
      const double l2 = l1 - r1 * (l1 - l0) / (r1 - r0);
      l0 = l1;
      r0 = r1;
      l1 = l2;
      r1 = trial(l1, q);
    }
    lat = l1;
    p = q;
  }
  return d * dt * n;
}

/// Root of f on [a, b] (f(a), f(b) of opposite signs) by bisection: the tests' own solver of
/// the closed forms, independent of the models' returns.
template <class F>
double bisect(F f, double a, double b) {
  double fa = f(a);
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (a + b), fm = f(m);
    if ((fm > 0) == (fa > 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// An aluminium foam of relative density ~0.1 (LS-DYNA *MAT_154 style, the slides' foam layer):
// E 100 MPa, nu 0.05, plateau 1.5 MPa, eps_D from rho*/rho_s = 0.1 and alpha = 2.12.
// Compacted: aluminium's bulk modulus.
constexpr double kFoamE = 100e6, kFoamNu = 0.05, kSp = 1.5e6, kGamma = 2e6, kAlpha2 = 4e6, kBeta = 2, kFoamKs = 76e9;
core::ModelSpec foamSpec(double plasticPoisson) {
  core::ModelSpec m;
  m.type = "crushable_foam";
  const double a2 = 9 * (1 - 2 * plasticPoisson) / (2 * (1 + plasticPoisson));
  m.params = {{"youngs_modulus", kFoamE}, {"poissons_ratio", kFoamNu},
              {"bulk_modulus", kFoamE / (3 * (1 - 2 * kFoamNu))}, {"shear_modulus", kFoamE / (2 * (1 + kFoamNu))},
              {"plateau_stress", kSp}, {"densification_strain", -(9 + a2) / (3 * a2) * std::log(0.1)},
              {"plastic_poissons_ratio", plasticPoisson}, {"hardening_gamma", kGamma},
              {"hardening_alpha2", kAlpha2}, {"hardening_beta", kBeta}, {"densified_bulk_modulus", kFoamKs}};
  return m;
}
double foamY(const core::ModelSpec& s, double e) {
  const double x = e / s.params.at("densification_strain");
  if (x >= 1) return 1e300;  // densified
  return kSp + kGamma * x + kAlpha2 * std::log(1 / (1 - std::pow(x, kBeta)));
}

}  // namespace

TEST(CrushableFoam, UniaxialCrushFollowsTheClosedForm) {
  // Uniaxial stress: sigma_hat = |sigma|, and eps_hat is the axial plastic strain, so
  // |sigma| = Y(|eps| - |sigma| / E) along the whole crush, plateau to densification.
  for (const double nup : {0.0, 0.2}) {
    const auto s = foamSpec(nup);
    auto m = createConstitutiveModel(s, "foam");
    auto p = one();
    const double epsD = s.params.at("densification_strain");
    double eps = 0, worst = 0;
    for (int stage = 0; stage < 80; ++stage) {
      eps += uniaxialStress(*m, p, -1.0, 5e-3, 10);  // 0.05 of compression (log strain) per stage
      const double sig = -p.stress[kXX][0];
      const double e = -eps;
      const double exact = bisect([&](double x) { return x - foamY(s, e - x / kFoamE); }, 0.0, e * kFoamE);
      worst = std::max(worst, std::fabs(sig - exact) / exact);
      if (p.eqps[0] > 0.9 * epsD) break;
    }
    EXPECT_LT(worst, 1e-7) << "nu_p " << nup;
    std::printf("uniaxial crush, nu_p %.1f: max |sigma - closed form| / closed form %.2e to eps_hat %.3f (eps_D %.3f), "
                "sigma %.3e Pa\n", nup, worst, p.eqps[0], epsD, -p.stress[kXX][0]);
    EXPECT_GT(p.eqps[0], 0.5 * epsD) << "crushed well into densification";
    EXPECT_NEAR(p.stress[kYY][0], 0.0, 1e-6 * std::fabs(p.stress[kXX][0]));
  }
}

TEST(CrushableFoam, HydrostaticCrushFollowsTheClosedForm) {
  // Pure compression: |sigma_m| = Y(eps_hat) sqrt(c) / alpha, eps_hat = (|eps_v| - |sigma_m| / K) sqrt(c) / alpha,
  // c = 1 + alpha^2 / 9; the deviator stays 0.
  const auto s = foamSpec(0.0);
  auto m = createConstitutiveModel(s, "foam");
  const CrushableFoam& foam = dynamic_cast<const CrushableFoam&>(*m);
  const double a = foam.alpha(), c = 1 + a * a / 9, Kf = s.params.at("bulk_modulus");
  EXPECT_NEAR(a, std::sqrt(4.5), 1e-15);
  auto p = one();
  const double d = -1.0 / 3, dt = 5e-3, L[9] = {d, 0, 0, 0, d, 0, 0, 0, d};
  double ev = 0, worst = 0, evLast = 0, eLast = 0, pLast = 0;
  for (int stage = 0; stage < 100; ++stage) {
    strain(*m, p, L, dt, 10);
    ev += 3 * d * dt * 10;
    if (p.vol[0] <= foam.denseVolumeRatio()) break;  // fully dense: the next test
    const double pm = -p.stress[kXX][0];
    evLast = ev, eLast = p.eqps[0], pLast = pm;
    const double exact =
        bisect([&](double x) { return x - foamY(s, (-ev - x / Kf) * std::sqrt(c) / a) * std::sqrt(c) / a; }, 0.0,
               -ev * Kf);
    worst = std::max(worst, std::fabs(pm - exact) / exact);
    EXPECT_NEAR(p.stress[kXY][0], 0.0, 1e-9 * pm);
    EXPECT_NEAR(p.stress[kXX][0], p.stress[kZZ][0], 1e-9 * pm);
    if (p.eqps[0] > 0.9 * s.params.at("densification_strain")) break;
  }
  EXPECT_LT(worst, 1e-7);
  EXPECT_GT(eLast, 0.5 * s.params.at("densification_strain"));
  std::printf("hydrostatic crush: max |p - closed form| / closed form %.2e to eps_v %.3f, eps_hat %.3f, p %.3e Pa\n",
              worst, evLast, eLast, pLast);
  EXPECT_NEAR(foam.denseVolumeRatio(), 0.1, 1e-12);  // rho_foam / rho_solid of the spec's eps_D
  // Below the yield surface the response is elastic: a small first step gives K eps_v.
  auto q = one();
  const double Ls[9] = {-1e-5, 0, 0, 0, -1e-5, 0, 0, 0, -1e-5};
  strain(*m, q, Ls, 1.0, 1);
  EXPECT_NEAR(q.stress[kXX][0], -3e-5 * Kf, 1e-9 * 3e-5 * Kf);
  EXPECT_EQ(q.eqps[0], 0.0);
}

// Past full density (V / V0 <= rho_foam / rho_solid = 0.1 here) the foam is its cell walls'
// solid: a hydrostatic crush goes on at the solid's bulk modulus (dp = K_s |tr D| dt exactly, the
// deviator 0, no more plastic strain), and the step's wave speed is the solid's.
TEST(CrushableFoam, HydrostaticCrushPastFullDensityTakesTheSolidsBulkModulus) {
  const auto s = foamSpec(0.0);
  auto m = createConstitutiveModel(s, "foam");
  const CrushableFoam& foam = dynamic_cast<const CrushableFoam&>(*m);
  auto p = one();
  const double d = -1.0 / 3, dt = 1e-3, L[9] = {d, 0, 0, 0, d, 0, 0, 0, d};
  int steps = 0;
  while (p.vol[0] > foam.denseVolumeRatio() && steps < 100000) {
    strain(*m, p, L, dt, 1);
    ++steps;
  }
  strain(*m, p, L, dt, 1);  // the first step at the dense state
  const double p1 = -p.stress[kXX][0], e1 = p.eqps[0];
  const int n = 300;  // ln J falls by a further 0.3
  strain(*m, p, L, dt, n);
  const double p2 = -p.stress[kXX][0];
  EXPECT_NEAR(p2 - p1, kFoamKs * 3 * std::fabs(d) * dt * n, 1e-9 * p2);
  EXPECT_NEAR(p.stress[kXX][0], p.stress[kYY][0], 1e-9 * p2);
  EXPECT_EQ(p.eqps[0], e1);
  EXPECT_LT(p.vol[0], 0.075);
  EXPECT_NEAR(m->maxSignalSpeed(p, 0, 1, 3),
              std::sqrt((kFoamKs + 4.0 / 3 * kFoamE / (2 * (1 + kFoamNu))) * p.vol[0] / p.mass[0]), 1e-9 * 6000);
  std::printf("hydrostatic crush past full density: p %.4e Pa at J %.4f (%.4e at J_d), wave speed %.0f m/s\n", p2,
              p.vol[0], p1, m->maxSignalSpeed(p, 0, 1, 3));
}

// ICE reads a crushable foam's volume from its crush curve (the `crush_curve` EOS,
// core/material/foam_crush_curve.h): the curve is this model's hydrostatic response, elastic,
// crushing and compacted, for nu_p 0 and 0.2 (alpha 2.12 and 1.5). Checked along a hydrostatic
// crush of the model to V/V0 0.07: its mean stress against the curve at -ln J, and the curve's
// inverse (the density ICE gives the foam at that pressure) against the particle's density.
TEST(CrushableFoam, IcesCrushCurveIsTheModelsHydrostaticResponse) {
  for (const double nup : {0.0, 0.2}) {
    const auto s = foamSpec(nup);
    auto m = createConstitutiveModel(s, "foam");
    const CrushableFoam& foam = dynamic_cast<const CrushableFoam&>(*m);
    core::FoamCrushParams f;
    f.bulkModulus = s.params.at("bulk_modulus"), f.thresholdPressure = 101325, f.referenceDensity = 270;
    f.hardening = {kSp, s.params.at("densification_strain"), nup, kGamma, kAlpha2, kBeta, kFoamKs};
    const core::FoamCrushCurve curve(f);
    EXPECT_NEAR(curve.denseVolumeRatio(), foam.denseVolumeRatio(), 1e-14);
    auto p = one();
    const double d = -1.0 / 3, dt = 2e-4, L[9] = {d, 0, 0, 0, d, 0, 0, 0, d};
    double worstP = 0, worstRho = 0;
    int elastic = 0, crushing = 0, dense = 0;
    double ev = 0;  // the volumetric log strain, J = exp(ev) exactly (the helper's F update is first order)
    while (p.vol[0] > 0.07) {
      for (int step = 0; step < 10; ++step) {
        for (int k = 0; k < 9; ++k) p.L[k][0] = L[k];
        ev -= dt;
        for (int k : {0, 4, 8}) p.F[k][0] = std::exp(ev / 3);
        p.vol[0] = p.vol0[0] * std::exp(ev);
        m->updateStress(p, 0, 1, dt);
      }
      const double J = p.vol[0], P = -p.stress[kXX][0];
      const double exact = curve.crushPressure(-std::log(J));
      worstP = std::max(worstP, std::fabs(P - exact) / exact);
      const double rho = curve.density(101325 + P);
      worstRho = std::max(worstRho, std::fabs(rho * J / 270 - 1));
      if (-std::log(J) < 1.5e6 * 0.5 / f.bulkModulus) ++elastic;
      else if (J > curve.denseVolumeRatio()) ++crushing;
      else ++dense;
    }
    EXPECT_GT(elastic, 0) << nup;
    EXPECT_GT(crushing, 100) << nup;
    EXPECT_GT(dense, 10) << nup;
    // The model integrates in steps (its return map, the split at J_d): 1e-6 of the pressure.
    EXPECT_LT(worstP, 1e-6) << nup;
    EXPECT_LT(worstRho, 1e-6) << nup;
    std::printf("nu_p %.1f: crush curve against the model's hydrostatic crush: |dP|/P %.2e, |drho|/rho %.2e; "
                "full density at %.4f, %.4e Pa\n",
                nup, worstP, worstRho, curve.denseVolumeRatio(), curve.densePressure());
  }
}

// A confined crush (uniaxial strain, the foam layer under the water shock) to 1 GPa of axial
// stress stays at the solid's density: without the lock-up the foam's own K (37 MPa) let it reach
// J = 0.012 at 300 us in the underwater scene.
TEST(CrushableFoam, ConfinedCrushToAGigapascalStopsAtTheSolidsDensity) {
  const auto s = foamSpec(0.0);
  auto m = createConstitutiveModel(s, "foam");
  const CrushableFoam& foam = dynamic_cast<const CrushableFoam&>(*m);
  auto p = one();
  const double L[9] = {-1.0, 0, 0, 0, 0, 0, 0, 0, 0};
  int steps = 0;
  while (-p.stress[kXX][0] < 1e9 && steps < 100000) {
    strain(*m, p, L, 1e-4, 1);
    ++steps;
  }
  EXPECT_GE(-p.stress[kXX][0], 1e9);
  EXPECT_GT(p.vol[0], 0.95 * foam.denseVolumeRatio());
  std::printf("confined crush: 1 GPa at J %.4f (J_d %.4f) after %d steps\n", p.vol[0], foam.denseVolumeRatio(), steps);
}

TEST(CowperSymonds, YieldStressScalesWithTheRateAtTwoRates) {
  // Uniaxial strain at rate d: equivalent strain rate 2 d / 3; on the surface q = (sy0 + H eps_p)
  // (1 + (2 d / (3 C))^(1/p)). The rates 10 and 1000 1/s with C 40.4, p 5 (mild steel's pair).
  core::ModelSpec s = spec("cowper_symonds");
  s.params["rate_c"] = 40.4;
  s.params["rate_p"] = 5;
  auto m = createConstitutiveModel(s, "polymer");
  EXPECT_STREQ(m->name(), "cowper_symonds");
  double qs[2];
  int k = 0;
  for (const double rate : {10.0, 1000.0}) {
    auto p = one();
    const double L[9] = {rate, 0, 0, 0, 0, 0, 0, 0, 0};
    strain(*m, p, L, 1e-2 / rate / 40, 40);  // to 1e-2, past yield at both rates
    const double sx = p.stress[0][0], sy = p.stress[1][0];
    const double q = std::fabs(sx - sy);  // uniaxial strain: sigma_yy = sigma_zz
    const double factor = 1 + std::pow(2 * rate / 3 / 40.4, 1.0 / 5);
    EXPECT_GT(p.eqps[0], 0);
    EXPECT_NEAR(q, (250e6 + 1e9 * p.eqps[0]) * factor, 1e-9 * q) << "rate " << rate;
    std::printf("cowper_symonds at %g 1/s: q %.6e Pa, closed form %.6e Pa (factor %.4f, eps_p %.4e)\n", rate, q,
                (250e6 + 1e9 * p.eqps[0]) * factor, factor, p.eqps[0]);
    qs[k++] = q;
  }
  EXPECT_GT(qs[1], 1.3 * qs[0]) << "the faster test flows at the higher stress";
  s.params["rate_c"] = 0;
  EXPECT_THROW((void)createConstitutiveModel(s, "polymer"), std::invalid_argument);
}

TEST(J2Plasticity, PiecewiseLinearWithFailureFollowsTheTableToFailure) {
  // The PVC of the underwater case: a tabulated curve (yield 45 MPa, hardening to 60 MPa at
  // eps_p 0.1) and failure at eps_p 0.15. Uniaxial strain at constant rate: on the surface q is
  // the table at eps_p (and, once eps_p passes 0.1, its last slope), the mean stress stays
  // elastic K eps; after failure no deviator, compression kept, tension dropped.
  const double Ep = 3e9, nup = 0.38, Kp = Ep / (3 * (1 - 2 * nup)), Gp = Ep / (2 * (1 + nup));
  core::ModelSpec s;
  s.type = "j2_plasticity";
  s.params = {{"bulk_modulus", Kp}, {"shear_modulus", Gp}, {"yield_stress", 45e6}, {"failure_strain", 0.15}};
  s.tables = {{"plastic_strain", {0, 0.02, 0.1}}, {"stress", {45e6, 55e6, 60e6}}};
  auto m = createConstitutiveModel(s, "pvc");
  auto table = [](double e) {
    if (e <= 0.02) return 45e6 + e * 10e6 / 0.02;
    return 55e6 + (e - 0.02) * 5e6 / 0.08;  // extrapolated with the last slope beyond 0.1
  };
  auto p = one();
  const double d = 1e-3, L[9] = {-d, 0, 0, 0, 0, 0, 0, 0, 0};
  double eps = 0;
  bool failedSeen = false;
  for (int step = 0; step < 400; ++step) {
    const double before = p.eqps[0];
    strain(*m, p, L, 1.0, 1);
    eps += d;
    const double mean = (p.stress[0][0] + p.stress[1][0] + p.stress[2][0]) / 3;
    const double q = std::fabs(p.stress[0][0] - p.stress[1][0]);
    if (p.failed[0] == 0.0) {
      if (p.eqps[0] > 0) {
        EXPECT_NEAR(q, table(p.eqps[0]), 1e-9 * q) << "step " << step;
      }
      EXPECT_NEAR(mean, -Kp * eps, 1e-9 * Kp * eps);
    } else {
      if (!failedSeen) {
        EXPECT_LT(before, 0.15) << "fails in the step that crosses the failure strain";
      }
      failedSeen = true;
      EXPECT_GE(p.eqps[0], 0.15);
      EXPECT_EQ(q, 0.0);
      EXPECT_NEAR(mean, -Kp * eps, 1e-9 * Kp * eps) << "compression kept after failure";
    }
  }
  ASSERT_TRUE(failedSeen);
  // Uniaxial strain: eps_p follows the axial strain as (2/3) of (eps - elastic part); at failure
  // the axial strain is near 0.15 * 3/2 + 2 sy / (3 * 2G).
  const double L2[9] = {2 * d, 0, 0, 0, 0, 0, 0, 0, 0};
  strain(*m, p, L2, 1.0, 300);  // back into tension: the failed particle carries nothing
  for (int k = 0; k < 6; ++k) EXPECT_EQ(p.stress[k][0], 0.0);
}

// The planar form of the linear-elastic update (1D / 2D layouts, out-of-plane components not
// stored) gives the 3D formula's bits for every stored component and the stress work.
TEST(LinearElastic, PlanarUpdateGivesTheBitsOfTheThreeDimensionalFormula) {
  auto model = createConstitutiveModel(spec("linear_elastic"), "test");
  ParticleSet full, planar;
  ParticleLayout layout;
  layout.dim = 2;
  planar.setLayout(layout);
  std::uint64_t state = 12345;
  auto rnd = [&]() {  // deterministic values in [-1, 1)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 4503599627370496.0 - 1.0;
  };
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    full.addParticle({0, 0, 0}, {0, 0, 0}, 1.0, 1.0 + 0.1 * rnd(), {0.5, 0.5, 0.5}, 0, 300, i);
    planar.addParticle({0, 0, 0}, {0, 0, 0}, 1.0, full.vol[static_cast<std::size_t>(i)], {0.5, 0.5, 0.5}, 0, 300, i);
    const auto k = static_cast<std::size_t>(i);
    // Some exact zeros too (a particle at rest, a pure shear) where the signs of zeros matter.
    const bool zero = i % 7 == 0;
    for (int c : {0, 1, 3, 4}) {
      const double l = zero ? 0.0 : 1e3 * rnd();
      full.L[c][k] = planar.L[c][k] = l;
    }
    for (int c : {kXX, kYY, kZZ, kXY}) {
      const double s = i % 11 == 0 ? 0.0 : 1e8 * rnd();
      full.stress[c][k] = planar.stress[c][k] = s;
    }
    full.work[k] = planar.work[k] = i % 5 == 0 ? 0.0 : rnd();
  }
  for (int step = 0; step < 3; ++step) {
    model->updateStress(full, 0, n, 1e-6);
    model->updateStress(planar, 0, n, 1e-6);
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    for (int c : {kXX, kYY, kZZ, kXY})
      EXPECT_EQ(std::signbit(full.stress[c][i]), std::signbit(planar.stress[c][i])) << "stress " << c << " particle " << i;
    for (int c : {kXX, kYY, kZZ, kXY}) ASSERT_EQ(full.stress[c][i], planar.stress[c][i]) << "stress " << c << " particle " << i;
    ASSERT_EQ(full.work[i], planar.work[i]) << "work, particle " << i;
  }
}
