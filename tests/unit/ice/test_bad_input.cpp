// Bad scene input gives clear errors: an EOS name that does not exist, a negative pressure or
// density in an initial state, volume fractions that do not sum to one in a region, a bad option.
#include <gtest/gtest.h>

#include "../../verification/ice/ice_test_scenes.h"
#include "test_comm.h"

using namespace mpmice;

namespace {

std::string errorOf(const core::Scene& s) {
  try {
    ice::IceSolver solver(s, test::comm());
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

core::Scene base() { return test::shockTube(10, {1, 0, 1}, {0.125, 0, 0.1}, 0.5, 0.2); }

// base() with water (stiffened gas) on both sides.
core::Scene waterBase() {
  core::Scene s = base();
  s.materials[0] = test::stiffenedGas("water", 4.4, 6e8);
  s.geometry[0].fill = s.geometry[1].fill = {{"water", 1.0}};
  return s;
}

}  // namespace

TEST(IceBadInput, UnknownEosName) {
  core::Scene s = base();
  s.materials[0].eos.type = "perfect_gas";
  const std::string m = errorOf(s);
  EXPECT_NE(m.find("perfect_gas"), std::string::npos) << m;
  EXPECT_NE(m.find("ideal_gas"), std::string::npos) << m;
  EXPECT_NE(m.find("materials.gas.eos"), std::string::npos) << m;
}

TEST(IceBadInput, NegativePressure) {
  core::Scene s = base();
  s.geometry[1].pressure = -5.0;
  const std::string m = errorOf(s);
  EXPECT_NE(m.find("geometry.right.pressure"), std::string::npos) << m;
  EXPECT_NE(m.find("-5"), std::string::npos) << m;
}

TEST(IceBadInput, NegativeDensity) {
  core::Scene s = base();
  s.geometry[0].density = -1.0;
  const std::string m = errorOf(s);
  EXPECT_NE(m.find("geometry.left.density"), std::string::npos) << m;
}

TEST(IceBadInput, FractionsThatDoNotSumToOne) {
  core::Scene s = base();
  s.materials.push_back(test::idealGas("helium", 1.67, 3116));
  s.geometry[0].fill = {{"gas", 0.5}, {"helium", 0.3}};
  const std::string m = errorOf(s);
  EXPECT_NE(m.find("geometry.left.fill"), std::string::npos) << m;
  EXPECT_NE(m.find("0.8"), std::string::npos) << m;
}

TEST(IceBadInput, UnknownOption) {
  core::Scene s = base();
  s.ice.advection = "third_order";
  EXPECT_NE(errorOf(s).find("ice.advection"), std::string::npos);
  s = base();
  s.ice.limiter = "koren";
  EXPECT_NE(errorOf(s).find("ice.limiter"), std::string::npos);
}

// Cavitation (docs/ice.md "Cavitation"): a cut-off at or above the liquid's starting pressure is
// named with the region; the semi-implicit pressure is refused with the alternative.
TEST(IceBadInput, CavitationCutoffAboveTheStartingPressure) {
  core::Scene s = waterBase();
  s.geometry[0].pressure = 2e5;
  s.geometry[1].pressure = 1e5;
  s.materials[0].cavitation = test::modelSpec("pressure_cutoff", {{"pressure", 1.5e5}});
  const std::string m = errorOf(s);
  EXPECT_NE(m.find("materials.water.cavitation.pressure"), std::string::npos) << m;
  EXPECT_NE(m.find("geometry.right"), std::string::npos) << m;
  EXPECT_NE(m.find("must lie below the liquid's ambient pressure"), std::string::npos) << m;
}

TEST(IceBadInput, CavitationBelowTheStiffenedGasFloorAndWithTheSemiImplicitPressure) {
  core::Scene s = waterBase();
  s.geometry[0].density = s.geometry[1].density = 1000;
  s.geometry[0].pressure = s.geometry[1].pressure = 1e5;
  s.materials[0].cavitation = test::modelSpec("pressure_cutoff", {{"pressure", -7e8}});
  std::string m = errorOf(s);
  EXPECT_NE(m.find("materials.water.cavitation.pressure"), std::string::npos) << m;
  EXPECT_NE(m.find("lowest pressure of its equation of state"), std::string::npos) << m;
  s.materials[0].cavitation = test::modelSpec("pressure_cutoff", {{"pressure", 0}});
  EXPECT_EQ(errorOf(s), "");
  s.ice.pressure_solver = "semi_implicit";
  m = errorOf(s);
  EXPECT_NE(m.find("materials.water.cavitation: not available with ice.pressure_solver: semi_implicit"),
            std::string::npos) << m;
  s.materials[0].cavitation = test::modelSpec("cut_off", {{"pressure", 0}});
  s.ice.pressure_solver = "explicit";
  m = errorOf(s);
  EXPECT_NE(m.find("unknown model 'cut_off'; valid: pressure_cutoff"), std::string::npos) << m;
}

