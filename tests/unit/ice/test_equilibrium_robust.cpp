// The equilibrium pressure at the extremes: stiffened-gas water against ideal-gas air at its real
// density (1.2 kg/m^3) with volume fractions from 1e-10 to 1 - 1e-10, water in tension, Mie-Gruneisen
// water compressed to 50 GPa, starting guesses far outside the admissible interval. Every pressure
// the solver evaluates must be admissible for every EOS (recorded by a wrapping EOS), the root must
// be the one built into the cell, and a cell without a root is a failure naming why and which
// material (also through IceSolver: the message names the material, the cell and the time).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "../../verification/ice/ice_test_scenes.h"
#include "ice/eos/eos.h"
#include "ice/pressure/equilibrium_pressure.h"
#include "ice/solver/health_check.h"
#include "test_comm.h"

using namespace mpmice;

namespace {
constexpr auto& spec = test::modelSpec;

// Forwards to an EOS and records the lowest pressure density() was asked about relative to the
// inner EOS's floor at that e (must stay > 0: the solver never leaves the admissible interval).
class RecordingEos final : public ice::Eos {
 public:
  explicit RecordingEos(std::unique_ptr<ice::Eos> inner) : Eos(inner->cv()), in_(std::move(inner)) {}
  using Eos::density;
  using Eos::pressure;
  using Eos::soundSpeed2;
  [[nodiscard]] const char* name() const override { return in_->name(); }
  void pressure(std::size_t n, const double* rho, const double* e, double* p) const override {
    in_->pressure(n, rho, e, p);
  }
  void density(std::size_t n, const double* p, const double* e, double* rho, double* drhodp) const override {
    for (std::size_t i = 0; i < n; ++i) {
      double f;
      in_->pressureFloor(1, &e[i], &f);
      minMargin = std::min(minMargin, p[i] - f);
      if (!std::isfinite(p[i])) nonFinite = true;
    }
    in_->density(n, p, e, rho, drhodp);
  }
  void soundSpeed2(std::size_t n, const double* rho, const double* e, double* c2) const override {
    in_->soundSpeed2(n, rho, e, c2);
  }
  void pressureFloor(std::size_t n, const double* e, double* pmin) const override { in_->pressureFloor(n, e, pmin); }
  [[nodiscard]] double internalEnergy(double rho, double p) const override { return in_->internalEnergy(rho, p); }
  mutable double minMargin = std::numeric_limits<double>::infinity();
  mutable bool nonFinite = false;

 private:
  std::unique_ptr<ice::Eos> in_;
};

std::unique_ptr<RecordingEos> water() {
  return std::make_unique<RecordingEos>(ice::makeEos(spec("stiffened_gas", {{"gamma", 4.4}, {"p_inf", 6e8}}), 4186));
}
std::unique_ptr<RecordingEos> air() {
  return std::make_unique<RecordingEos>(ice::makeEos(spec("ideal_gas", {{"gamma", 1.4}}), 717.5));
}
// The filled lattices' polymer (K = 2.78e9 Pa, solid_bulk with its stress-free pressure p_ref and
// density rho0) and a silicone filler (a stiffened gas), both with cv 1500 J/(kg K).
std::unique_ptr<RecordingEos> polymer(double pRef, double rho0) {
  return std::make_unique<RecordingEos>(ice::makeEos(
      spec("solid_bulk", {{"bulk_modulus", 2.78e9}, {"threshold_pressure", pRef}, {"reference_density", rho0}}), 1500));
}
std::unique_ptr<RecordingEos> silicone(double gamma, double pInf) {
  return std::make_unique<RecordingEos>(ice::makeEos(spec("stiffened_gas", {{"gamma", gamma}, {"p_inf", pInf}}), 1500));
}
std::unique_ptr<RecordingEos> mgWater() {
  return std::make_unique<RecordingEos>(ice::makeEos(
      spec("mie_gruneisen", {{"reference_density", 1000}, {"sound_speed", 1480}, {"slope", 1.75},
                             {"gruneisen", 0.28}, {"reference_pressure", 1e5}}), 4186));
}

// Cells whose equilibrium is pStar: material r has energy e[r] and volume fraction theta[r] there
// (m_r / V = theta_r rho_r(pStar, e_r)). Solves from each guess and checks the root, the
// fractions and that every evaluated pressure was admissible.
void expectRoot(const std::vector<RecordingEos*>& eos, const std::vector<double>& e, double pStar,
                const std::vector<double>& thetas0, const std::vector<double>& guesses) {
  const std::size_t nm = eos.size();
  std::vector<const ice::Eos*> ce(eos.begin(), eos.end());
  ice::EquilibriumPressure eq(ce, 1e-11, 100);
  for (const double th0 : thetas0) {
    const std::vector<double> theta = nm == 2 ? std::vector<double>{th0, 1 - th0}
                                              : std::vector<double>{th0, 0.5 * (1 - th0), 0.5 * (1 - th0)};
    std::vector<std::vector<double>> rho(nm), en(nm), micro(nm);
    std::vector<const double*> rp, ep;
    std::vector<double*> mp;
    const std::size_t nc = guesses.size();
    for (std::size_t r = 0; r < nm; ++r) {
      rho[r].assign(nc, theta[r] * eos[r]->density(pStar, e[r]));
      en[r].assign(nc, e[r]);
      micro[r].assign(nc, 0.0);
      rp.push_back(rho[r].data());
      ep.push_back(en[r].data());
      mp.push_back(micro[r].data());
    }
    std::vector<double> p = guesses;
    std::vector<int> it(nc);
    std::vector<std::int64_t> cells;
    for (std::size_t c = 0; c < nc; ++c) cells.push_back(static_cast<std::int64_t>(c));
    for (RecordingEos* x : eos) x->minMargin = std::numeric_limits<double>::infinity();
    const auto fails = eq.solve(cells, rp, ep, p.data(), mp, it.data());
    ASSERT_TRUE(fails.empty()) << "theta " << th0;
    for (std::size_t c = 0; c < nc; ++c) {
      EXPECT_NEAR(p[c], pStar, 1e-8 * std::max(std::abs(pStar), 1e5)) << "theta " << th0 << " guess " << guesses[c];
      double sum = 0;
      for (std::size_t r = 0; r < nm; ++r) sum += rho[r][c] / micro[r][c];
      EXPECT_NEAR(sum, 1.0, 1e-10) << "theta " << th0;
      EXPECT_LE(it[c], 100);
    }
    for (RecordingEos* x : eos) {
      EXPECT_GT(x->minMargin, 0.0) << x->name() << ": a pressure at or below its floor was evaluated";
      EXPECT_FALSE(x->nonFinite) << x->name();
    }
  }
}

const std::vector<double> kThetas = {1e-10, 1e-6, 0.5, 1 - 1e-6, 1 - 1e-10};
// Guesses: the root's scale, far above, inside water's tension range, below every floor, NaN.
const std::vector<double> kGuesses = {1e5, 1e12, -5.9e8, -1e10, std::numeric_limits<double>::quiet_NaN()};
}  // namespace

TEST(IceEquilibriumRobust, WaterAgainstAirAtRealDensityAndExtremeFractions) {
  auto w = water(), a = air();
  const double ew = w->internalEnergy(1000.0, 1e5), ea = a->internalEnergy(1.2, 1e5);
  for (const double pStar : {1e5, 1e3, 1.419e7, 1e10})
    expectRoot({w.get(), a.get()}, {ew, ea}, pStar, kThetas, kGuesses);
}

TEST(IceEquilibriumRobust, WaterHotAndColdAgainstAir) {
  // Water at the energy of 1 GPa and 1000 kg/m^3 (a shocked state) against cold thin air.
  auto w = water(), a = air();
  const double ew = w->internalEnergy(1000.0, 1e9), ea = a->internalEnergy(0.01, 1e3);
  for (const double pStar : {2e3, 3e8}) expectRoot({w.get(), a.get()}, {ew, ea}, pStar, kThetas, kGuesses);
}

TEST(IceEquilibriumRobust, StiffenedWaterInTensionAgainstStiffenedWater) {
  // Two stiffened gases: the equilibrium may lie in tension, down to -p_inf of the stiffer floor.
  auto w = water();
  auto w2 = std::make_unique<RecordingEos>(ice::makeEos(spec("stiffened_gas", {{"gamma", 7.15}, {"p_inf", 3e8}}), 4186));
  const double e1 = w->internalEnergy(1000.0, 1e5), e2 = w2->internalEnergy(1000.0, 1e5);
  for (const double pStar : {-2.9e8, -1e7, 1e5, 5e9}) expectRoot({w.get(), w2.get()}, {e1, e2}, pStar, kThetas, kGuesses);
}

TEST(IceEquilibriumRobust, MieGruneisenWaterAgainstAirAndStiffenedGas) {
  auto mg = mgWater(), a = air(), w = water();
  const double em = 0.0, ea = a->internalEnergy(1.2, 1e5), ew = w->internalEnergy(1000.0, 1e5);
  for (const double pStar : {1e5, 1e8, 5e10}) {
    expectRoot({mg.get(), a.get()}, {em, ea}, pStar, kThetas, kGuesses);
    expectRoot({mg.get(), a.get(), w.get()}, {em, ea, ew}, pStar, kThetas, kGuesses);
  }
  // Compressed towards the Hugoniot's singular density rho0 s / (s - 1): stays below it.
  EXPECT_LT(mg->density(1e13, 0.0), 1000.0 * 1.75 / 0.75);
  EXPECT_GT(mg->density(1e13, 0.0), 2000.0);
  // Mie-Gruneisen against itself in tension (no floor): the root is found below zero.
  auto mg2 = mgWater();
  expectRoot({mg.get(), mg2.get()}, {em, 1e4}, -5e7, kThetas, {1e5, 1e12, -1e10});
}

TEST(IceEquilibriumRobust, NoAdmissibleStateNamesTheMaterial) {
  auto w = water(), a = air();
  ice::EquilibriumPressure eq({w.get(), a.get()}, 1e-11, 100);
  std::vector<double> rw = {500.0}, ra = {0.6}, ew = {1e6}, ea = {-10.0}, p = {1e5}, mw(1), ma(1);
  std::vector<int> it(1);
  const auto fails = eq.solve({0}, {rw.data(), ra.data()}, {ew.data(), ea.data()}, p.data(), {mw.data(), ma.data()},
                              it.data());
  ASSERT_EQ(fails.size(), 1u);
  EXPECT_EQ(fails[0].kind, ice::EquilibriumFailure::Kind::NoAdmissibleState);
  EXPECT_EQ(fails[0].material, 1);
}

TEST(IceEquilibriumRobust, NoRootAboveTheFloorIsAFailureNotAClamp) {
  // Two stiffened gases that fill only 0.8 of the cell even at the floor (p -> -3e8, the larger of
  // the two -p_inf; their densities only grow above it): no admissible root.
  auto w = water();
  auto w2 = std::make_unique<RecordingEos>(ice::makeEos(spec("stiffened_gas", {{"gamma", 7.15}, {"p_inf", 3e8}}), 4186));
  const double e1 = 1e6, e2 = 1e6;
  const double F = -3e8;
  std::vector<double> r1 = {0.5 * w->density(F, e1)}, r2 = {0.3 * w2->density(F * (1 - 1e-12), e2)};
  std::vector<double> en1 = {e1}, en2 = {e2}, p = {1e5}, m1(1), m2(1);
  std::vector<int> it(1);
  ice::EquilibriumPressure eq({w.get(), w2.get()}, 1e-11, 200);
  const auto fails = eq.solve({0}, {r1.data(), r2.data()}, {en1.data(), en2.data()}, p.data(), {m1.data(), m2.data()},
                              it.data());
  ASSERT_EQ(fails.size(), 1u);
  EXPECT_EQ(fails[0].kind, ice::EquilibriumFailure::Kind::NoRootAboveFloor);
  EXPECT_EQ(fails[0].material, 1);
  EXPECT_DOUBLE_EQ(fails[0].floor, F);
  EXPECT_GT(w->minMargin, 0.0);
  EXPECT_GT(w2->minMargin, 0.0);
}

TEST(IceEquilibriumRobust, SolverMessageNamesMaterialCellAndTime) {
  core::Scene s;
  s.name = "water_air";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Outflow;
  s.time.end = 1.0;
  s.materials = {test::stiffenedGas("water", 4.4, 6e8), test::idealGas("air")};
  s.geometry = {test::region("mix", test::box({0, 0, 0}, {1, 1, 1}), {{"water", 0.5}, {"air", 0.5}}, 1e5, 500)};
  ice::IceSolver sol(s, test::comm());
  sol.state().mat[1].eint(4, 0, 0) = -1.0;  // air with no admissible state in cell 4
  try {
    sol.computeEquilibriumPressure();
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    for (const std::string part : {"no equilibrium pressure", "cell (4,0,0)", "x = (0.45) m", "t = 0", "'air'",
                                   "no admissible state", "-1 J/kg"})
      EXPECT_NE(msg.find(part), std::string::npos) << "'" << part << "' not in: " << msg;
  }
}

// An absent fluid's density where its law has none at the cell's pressure: helium (ideal gas)
// absent from water under tension (p < 0 after a blast's rarefaction) took rho = p / ((gamma - 1)
// e) < 0 from the Newton iterate, so a specific volume of about -90 m^3/kg; a helium trace advected
// into the cell later kept it as its Lagrangian value and the health check stopped the run
// (superbee, 2D, water at -1e6 Pa, t = 3.0e-4 s, at every CFL from 0.2 to 1). Now the absent
// fluid keeps a positive density (absentDensity's): the run completes and every fluid's specific
// volume stays positive in every cell, present or not.
TEST(IceEquilibriumRobust, AbsentGasInWaterUnderTensionKeepsAPositiveVolume) {
  const char* yaml = R"(scene: blast_three_fluids
mesh: {dim: 2, lower: [0.0, 0.0], upper: [1.0, 1.0], cells: [48, 40]}
time: {end: 4.0e-4, cfl: 0.4}
materials:
  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}, specific_heat: 717.5}
  - {name: helium, kind: fluid, eos: {type: ideal_gas, gamma: 1.66}, specific_heat: 3116}
  - {name: water, kind: fluid, eos: {type: stiffened_gas, gamma: 4.4, p_inf: 6.0e8}, specific_heat: 4186}
geometry:
  - {name: air, shape: {type: box, lo: [0.0, 0.0], hi: [1.0, 1.0]}, material: air, pressure: 1.0e5, density: 1.2, velocity: [30.0, -20.0]}
  - {name: he, shape: {type: sphere, center: [0.3, 0.4], radius: 0.15}, material: helium, pressure: 1.0e7, density: 2.0}
  - {name: w, shape: {type: box, lo: [0.6, 0.1], hi: [0.8, 0.7]}, material: water, pressure: 1.0e5, density: 1000.0}
boundary: {x-: noslip_wall, x+: outflow, y-: slip_wall, y+: noslip_wall}
ice: {limiter: superbee}
output: {enabled: false}
)";
  ice::IceSolver s(core::parseScene(yaml, "blast_three_fluids.yaml"), test::comm());
  double minP = 0;
  while (s.time() < 4.0e-4 * (1 - 1e-12)) {
    s.step();
    ice::checkHealth(s);  // what the programs run after every step
    core::forEach(s.ownedBox(), [&](int i, int j, int k) {
      minP = std::min(minP, s.pressure()(i, j, k));
      for (const auto& m : s.state().mat) ASSERT_GT(m.spvol(i, j, k), 0.0) << m.name << " (" << i << "," << j << ") step " << s.steps();
    });
  }
  EXPECT_LT(minP, -1e5);  // the water went under tension (the case this covers)
}

// A solid_bulk trace beside a liquid that is short of its volume at p = 0 (silicone drained from a
// lattice's pore, 1 Pa s filled run at 1000 1/s): the solid's tension branch rho0 (p / p_ref)^(p_ref / K)
// (p_ref / K = 3.6e-5 for the polymer) fills the deficit only at p ~ 1e-150 .. 1e-250 Pa. The root
// lies hundreds of decades above the solid's floor (0); bisection linear in p reached 1e-30 after
// 100 iterations and the run stopped. Now it is bracketed by steps of 2^-1, 2^-2, 2^-4, ... towards
// the floor: found within 60 iterations to the residual, p > 0, never at or below a floor.
TEST(IceEquilibriumRobust, SolidTraceFillsALiquidsDeficitDecadesAboveTheFloor) {
  auto solid = polymer(1e5, 1200);
  auto liquid = silicone(4.4, 1.7e8);
  const double es = 1500 * 293.0, el = 1500 * 293.0;
  ice::EquilibriumPressure eq({solid.get(), liquid.get()}, 1e-11, 100);
  for (const double pStar : {1e-20, 1e-150, 1e-250}) {
    for (const double thetaS : {1e-6, 1e-3, 0.3}) {
      const std::vector<double> guesses = {5e7, 1e5, 1e12, -1e10, std::numeric_limits<double>::quiet_NaN()};
      const std::size_t nc = guesses.size();
      std::vector<double> rs(nc, thetaS * solid->density(pStar, es)), rl(nc, (1 - thetaS) * liquid->density(pStar, el));
      std::vector<double> ens(nc, es), enl(nc, el), ms(nc), ml(nc), p = guesses;
      std::vector<int> it(nc);
      std::vector<std::int64_t> cells;
      for (std::size_t c = 0; c < nc; ++c) cells.push_back(static_cast<std::int64_t>(c));
      solid->minMargin = liquid->minMargin = std::numeric_limits<double>::infinity();
      const auto fails = eq.solve(cells, {rs.data(), rl.data()}, {ens.data(), enl.data()}, p.data(),
                                  {ms.data(), ml.data()}, it.data());
      ASSERT_TRUE(fails.empty()) << "p* " << pStar << " theta_s " << thetaS << ": " << fails.size()
                                 << " failures, first at p = " << fails[0].p << " after " << fails[0].iterations;
      for (std::size_t c = 0; c < nc; ++c) {
        EXPECT_GT(p[c], 0.0);
        EXPECT_NEAR(rs[c] / ms[c] + rl[c] / ml[c], 1.0, 1e-11) << "p* " << pStar << " guess " << guesses[c];
        // The volume depends on ln p with slope theta_s p_ref / K: the root to 1e-11 of that.
        if (thetaS >= 1e-3) {
          EXPECT_NEAR(std::log(p[c] / pStar), 0.0, 1e-11 / (thetaS * 3.6e-5)) << "p* " << pStar;
        }
        EXPECT_LE(it[c], 60) << "p* " << pStar << " theta_s " << thetaS << " guess " << guesses[c];
      }
      EXPECT_GT(solid->minMargin, 0.0);
      EXPECT_GT(liquid->minMargin, 0.0);
    }
  }
}

// The same liquid further short of its volume than the solid trace can fill at any positive double
// pressure (the root would lie near 1e-400 Pa): a failure saying there is no root above the floor,
// which the solid sets, within the iteration limit, not a spin to the limit or a clamp.
TEST(IceEquilibriumRobust, SolidTraceThatCannotFillTheDeficitIsNoRootAboveItsFloor) {
  auto solid = polymer(1e5, 1200);
  auto liquid = silicone(4.4, 1.7e8);
  const double es = 1500 * 293.0, el = 1500 * 293.0, thetaS = 1e-3;
  // v_s(1e-400) = v_s(1e-300) (1e-100)^(-p_ref / K): from the law's closed form, out of double range.
  const double vs = 1.0 / solid->density(1e-300, es) * std::pow(10.0, 100 * 1e5 / 2.78e9);
  const double ms0 = thetaS / vs;
  std::vector<double> rs = {ms0}, rl = {(1 - thetaS) * liquid->density(0.0, el)}, ens = {es}, enl = {el}, m1(1), m2(1);
  std::vector<double> p = {5e7};
  std::vector<int> it(1);
  ice::EquilibriumPressure eq({solid.get(), liquid.get()}, 1e-11, 100);
  const auto fails = eq.solve({0}, {rs.data(), rl.data()}, {ens.data(), enl.data()}, p.data(), {m1.data(), m2.data()},
                              it.data());
  ASSERT_EQ(fails.size(), 1u);
  EXPECT_EQ(fails[0].kind, ice::EquilibriumFailure::Kind::NoRootAboveFloor);
  EXPECT_EQ(fails[0].material, 0);
  EXPECT_EQ(fails[0].floor, 0.0);
  EXPECT_LT(fails[0].iterations, 60);
  EXPECT_GT(solid->minMargin, 0.0);
}

// The same kind of root 150-300 decades above the floor with the solid's stress-free pressure at the
// filled lattices' 50 MPa ambient (p_ref / K = 0.018 for the polymer): the cell at the open face
// where a polymer particle torn from an 8-cells-per-edge lattice (a = 3.5 mm, 100 Pa s) left the
// specimen, silicone short of its volume beside it. The steps towards the floor (2^-1, 2^-2, 2^-4,
// ... of the distance) reached 1.5e-176 .. 4.5e-172 Pa from warm starts at 1e-22 .. 3e-18 Pa, just
// above the root near 1e-177 Pa; the next step (2^-1024 of the distance) underflowed to the floor
// and the solve reported no root above it (the run stopped at 336 us). A step that would pass the
// smallest normal double above the floor now stops there, which brackets the root (or, if the
// materials do not fill the cell even there, is the failure of the test above). Before, 1013 of
// these 3720 solves failed (every cell from some warm starts).
TEST(IceEquilibriumRobust, SolidTraceRootBetweenTheLastStepAndTheSmallestDouble) {
  auto solid = polymer(5e7, 1180);
  auto liquid = silicone(1.62, 5.4877e8);
  ice::EquilibriumPressure eq({solid.get(), liquid.get()}, 1e-11, 100);
  // The run's cell first: silicone 814.92 kg/m^3 of the cell at e 1.398e6 J/kg, polymer 0.1169.
  std::vector<double> rs = {0.116936292}, rl = {814.9244763}, es = {194053.1845}, el = {1397839.487};
  for (const double pStar : {1e-160, 1e-200, 1e-250, 1e-290, 1e-305}) {
    const double thetaS = 0.2;
    rs.push_back(thetaS * solid->density(pStar, es[0]));
    rl.push_back((1 - thetaS) * liquid->density(pStar, el[0]));
    es.push_back(es[0]);
    el.push_back(el[0]);
  }
  const std::size_t nc = rs.size();
  // Warm starts at every decade from 1e-300 to 1e9 Pa (the run's cell failed from 1e-22 .. 3e-18:
  // its last step landed at 1.5e-176 .. 4.5e-172, above the root).
  std::vector<double> guesses;
  for (int k = -300; k <= 9; ++k)
    for (const double m : {1.0, 3.0}) guesses.push_back(m * std::pow(10.0, k));
  for (const double guess : guesses) {
    std::vector<double> ms(nc), ml(nc), p(nc, guess);
    std::vector<int> it(nc);
    std::vector<std::int64_t> cells;
    for (std::size_t c = 0; c < nc; ++c) cells.push_back(static_cast<std::int64_t>(c));
    solid->minMargin = liquid->minMargin = std::numeric_limits<double>::infinity();
    const auto fails = eq.solve(cells, {rs.data(), rl.data()}, {es.data(), el.data()}, p.data(), {ms.data(), ml.data()},
                                it.data());
    ASSERT_TRUE(fails.empty()) << "guess " << guess << ": " << fails.size() << " failures, first in cell "
                               << fails[0].cell << " at p = " << fails[0].p << " after " << fails[0].iterations;
    for (std::size_t c = 0; c < nc; ++c) {
      EXPECT_GT(p[c], 0.0) << "cell " << c;
      EXPECT_NEAR(rs[c] / ms[c] + rl[c] / ml[c], 1.0, 1e-11) << "cell " << c << " guess " << guess;
      EXPECT_LE(it[c], 60) << "cell " << c << " guess " << guess;
    }
    EXPECT_GT(p[0], 1e-190);  // the run's cell: the root near 1e-177 Pa
    EXPECT_LT(p[0], 1e-170);
    EXPECT_GT(solid->minMargin, 0.0);
    EXPECT_GT(liquid->minMargin, 0.0);
  }
}

// A solid's smear of 1e-15 kg (5.8e-8 kg/m^3 of the cell) beside silicone short of its volume at
// p = 0: the state of the filled lattice a = 4.0 mm, 1 Pa s, 4 cells per edge at time.cfl 0.05 where
// it stopped (131.9 us, "no equilibrium pressure ... down to the lower end 0 Pa of material
// 'polymer'"): the solid's tension branch would fill the deficit only near 1e-460 Pa. Under the
// trace rule the solid, 7e-11 of the cell's fluid mass, is held at the volume its particles give it
// (its own pressure there, 5e7 Pa, is above the cell's), so the liquid takes the tension it takes
// without the smear (-8.93 MPa); without the rule the cell has no root above the solid's floor.
TEST(IceEquilibriumRobust, ASolidTraceIsHeldAtItsParticlesVolumeBesideALiquidInTension) {
  auto solid = polymer(5e7, 1180);
  auto liquid = silicone(1.62, 5.4877e8);
  const double rhoS = 5.798129564e-08, rhoL = 867.169486, eS = 126729.945, eL = 1636919.543, vS = 1.0 / 1181.0;
  std::vector<double> rs = {rhoS}, rl = {rhoL}, es = {eS}, el = {eL}, vs = {vS}, vl = {1.0 / 870.0};
  const std::vector<const double*> carried = {vs.data(), vl.data()};
  for (const double traceY : {1e-6, 0.0}) {
    ice::EquilibriumPressure eq({solid.get(), liquid.get()}, 1e-11, 100, {false, true}, traceY);
    for (const double guess : {5e7, 1e5, -1e6}) {
      std::vector<double> ms(1), ml(1), p = {guess};
      std::vector<int> it(1);
      solid->minMargin = liquid->minMargin = std::numeric_limits<double>::infinity();
      const auto fails = eq.solve({0}, {rs.data(), rl.data()}, {es.data(), el.data()}, p.data(), {ms.data(), ml.data()},
                                  it.data(), &carried);
      if (traceY == 0) {  // the run's failure
        ASSERT_EQ(fails.size(), 1u) << "guess " << guess;
        EXPECT_EQ(fails[0].kind, ice::EquilibriumFailure::Kind::NoRootAboveFloor);
        EXPECT_EQ(fails[0].material, 0);
        continue;
      }
      ASSERT_TRUE(fails.empty()) << "guess " << guess << ": failed at p = " << fails[0].p;
      // The solid held at its particles' density; the liquid fills the rest at its own pressure.
      EXPECT_DOUBLE_EQ(ms[0], 1.0 / vS);
      const double thetaS = rhoS * vS, rhoLiquid = rhoL / (1.0 - thetaS);
      const double pLiquid = (1.62 - 1.0) * rhoLiquid * eL - 1.62 * 5.4877e8;  // the stiffened gas at it
      EXPECT_NEAR(p[0], pLiquid, 1e-6 * std::abs(pLiquid)) << "guess " << guess;
      EXPECT_LT(p[0], -8e6);
      EXPECT_NEAR(rs[0] / ms[0] + rl[0] / ml[0], 1.0, 1e-11);
      ASSERT_EQ(eq.heldTraces().size(), 1u);
      EXPECT_EQ(eq.heldTraces()[0].first, 0);
      EXPECT_GT(liquid->minMargin, 0.0);
    }
  }
}

// A liquid with the cavitation cut-off p_c = 0 beside a solid_bulk solid, whose floor is 0 too:
// the cut-off ties the solid's floor and is the cell's. Short of its volume at p = 0, the liquid
// cavitates there (p = 0, listed in cavitated(), the solid at its limit from above, the liquid
// taking the rest of the cell) instead of the solid's tension branch filling the deficit near
// 1e-150 Pa; with enough liquid the root lies above 0 and is found as usual.
TEST(IceEquilibriumRobust, ACutOffAtTheSolidsFloorCavitatesThere) {
  auto solid = polymer(1e5, 1200);
  auto liquid = silicone(4.4, 1.7e8);
  liquid->setCavitationPressure(0.0);
  const double es = 1500 * 293.0, el = 1500 * 293.0, thetaS = 0.3;
  const double rhoS = thetaS * solid->density(1e-9, es);
  // Cell 0: the liquid 1 % short of its volume at p = 0 (a cavity); cell 1: at 2e5 Pa (a root).
  std::vector<double> rs = {rhoS, thetaS * solid->density(2e5, es)},
                      rl = {0.99 * (1 - thetaS) * liquid->density(0.0, el), (1 - thetaS) * liquid->density(2e5, el)};
  std::vector<double> ens = {es, es}, enl = {el, el}, ms(2), ml(2), p = {5e7, 5e7};
  std::vector<int> it(2);
  ice::EquilibriumPressure eq({solid.get(), liquid.get()}, 1e-11, 100);
  const auto fails = eq.solve({0, 1}, {rs.data(), rl.data()}, {ens.data(), enl.data()}, p.data(),
                              {ms.data(), ml.data()}, it.data());
  ASSERT_TRUE(fails.empty());
  EXPECT_EQ(p[0], 0.0);
  ASSERT_EQ(eq.cavitated().size(), 1u);
  EXPECT_EQ(eq.cavitated()[0], (std::pair<int, std::int64_t>{1, 0}));
  EXPECT_NEAR(rs[0] / ms[0] + rl[0] / ml[0], 1.0, 1e-12);                 // the liquid takes the rest
  EXPECT_LT(ml[0], liquid->density(0.0, el));                                // below rho_c: the cavity
  EXPECT_NEAR(ms[0], solid->density(1e-9, es), 1e-6 * ms[0]);               // the solid at its limit
  EXPECT_NEAR(p[1], 2e5, 1e-6 * 2e5);
  EXPECT_GT(solid->minMargin, 0.0);
}

// Warm starts far below the root with nothing above it seen: a gas trace filling 0.8 of a cell whose
// last pressure was a solid trace's 1e-150 Pa (lattice, a = 4.0 mm, 1 Pa s at 1000 1/s: the pores'
// liquid drained, the buffer gas arriving), and the solid trace's own log-like root approached from
// 1e-250 Pa. Newton from below gains a factor 2 (the gas, f ~ 1 - B / p) or 1 + ln(root / p) (the
// solid) a step: 100 iterations reached 7.5e-10 Pa of a root near 1e-2 and the run stopped. The
// distance above the floor now grows by 2^2, 2^4, 2^8, ... after two slow steps.
TEST(IceEquilibriumRobust, WarmStartsHundredsOfDecadesBelowTheRoot) {
  auto solid = polymer(1e5, 1200);
  auto liquid = silicone(4.4, 1.7e8);
  auto gas = air();
  const double es = 1500 * 293.0, el = 1500 * 293.0, eg = 717.5 * 293.0;
  const std::vector<double> guesses = {1e-150, 1e-250, 1e-300, 1e-20};
  const std::size_t nc = guesses.size();
  std::vector<std::int64_t> cells;
  for (std::size_t c = 0; c < nc; ++c) cells.push_back(static_cast<std::int64_t>(c));
  for (const double pStar : {1e-2, 1e3, 1e-20}) {
    // liquid 0.2, solid trace 1e-3, gas the rest (0.799) at pStar.
    std::vector<double> rs(nc, 1e-3 * solid->density(pStar, es)), rl(nc, 0.2 * liquid->density(pStar, el)),
        rg(nc, 0.799 * gas->density(pStar, eg));
    std::vector<double> ens(nc, es), enl(nc, el), eng(nc, eg), ms(nc), ml(nc), mg(nc), p = guesses;
    std::vector<int> it(nc);
    ice::EquilibriumPressure eq({solid.get(), liquid.get(), gas.get()}, 1e-11, 100);
    const auto fails = eq.solve(cells, {rs.data(), rl.data(), rg.data()}, {ens.data(), enl.data(), eng.data()},
                                p.data(), {ms.data(), ml.data(), mg.data()}, it.data());
    ASSERT_TRUE(fails.empty()) << "p* " << pStar << ": first failure at p = " << fails[0].p << " after "
                               << fails[0].iterations << " iterations";
    for (std::size_t c = 0; c < nc; ++c) {
      EXPECT_NEAR(p[c] / pStar, 1.0, 1e-9) << "p* " << pStar << " guess " << guesses[c];
      EXPECT_LE(it[c], 60) << "p* " << pStar << " guess " << guesses[c];
    }
    // Without the gas: the solid trace's root at 1e-150 .. 1e-20 from below.
    std::vector<double> none(nc, 0.0);
    for (double& r : rl) r = (1 - 1e-3) / 0.2 * r;  // the liquid fills the rest at pStar
    for (double& x : p) x = 1e-300;
    const auto f2 = eq.solve(cells, {rs.data(), rl.data(), none.data()}, {ens.data(), enl.data(), eng.data()},
                             p.data(), {ms.data(), ml.data(), mg.data()}, it.data());
    ASSERT_TRUE(f2.empty()) << "p* " << pStar;
    for (std::size_t c = 0; c < nc; ++c) {
      EXPECT_NEAR(rs[c] / ms[c] + rl[c] / ml[c], 1.0, 1e-11) << "p* " << pStar;
      EXPECT_LE(it[c], 60) << "p* " << pStar << " (solid trace from 1e-300)";
    }
  }
  EXPECT_GT(solid->minMargin, 0.0);
  EXPECT_GT(gas->minMargin, 0.0);
}
