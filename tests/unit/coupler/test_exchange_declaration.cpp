// Issue 14 "only what a scene needs": what each side declares from the scene, what the two
// declarations agree to move, and the error when they do not agree.
#include <gtest/gtest.h>

#include <string>

#include "coupler/launch/handshake.h"
#include "couplings/volume/common/exchange_declaration.h"

namespace mpmice::coupler {
namespace {

std::string lists(const FieldUses& u, const core::Scene& scene) {
  std::string out;
  for (ExchangePoint p : kExchangePoints) {
    std::size_t slot = 0;
    for (int m : scene.solids()) out += describeUses(u.of(p, slot++), p, scene.materials[m].name) + "\n";
  }
  return out;
}

TEST(ExchangeDeclaration, SeedCylinderMovesTwoComponentsOfEachVectorInTwoDimensions) {
  const core::Scene scene = core::loadScene(SEED_CYLINDER);
  const FieldUses travel = agree(scene, solidDeclaration(scene), fluidDeclaration(scene));
  EXPECT_EQ(lists(travel, scene),
            "steel: mass velocity(2) temperature specific_volume\n"
            "steel: pressure_force(2) pressure\n"
            "steel: lagrangian_momentum(2) coupling_work volume_change\n"
            "steel: exchange_momentum(2) exchange_energy\n");
  EXPECT_EQ(travel.valuesPerCell(), 15);
  EXPECT_EQ(FieldUses::everything(1).valuesPerCell(), 19);
}

// The flap's scene also moves its volume with MPM's face transport (coupling.solid_transport:
// mpm): the face density and flux, dim components each, with the solid state.
TEST(ExchangeDeclaration, FlapWithHeatExchangeMovesTheExchangeEnergy) {
  const core::Scene scene = core::loadScene(FLAP_MPMICE);
  const FieldUses travel = agree(scene, solidDeclaration(scene), fluidDeclaration(scene));
  EXPECT_EQ(lists(travel, scene),
            "flap: mass velocity(2) temperature specific_volume face_density(2) face_flux(2)\n"
            "flap: pressure_force(2) pressure\n"
            "flap: lagrangian_momentum(2) coupling_work volume_change\n"
            "flap: exchange_momentum(2) exchange_energy\n");
}

// Without a momentum coefficient no momentum increment moves; the exchange energy always does (it
// also carries the solids' share of the Lagrangian energy correction: with K = H = 0 not moving it
// lost that share, MpmIceEnergyBudget's no-exchange variant).
TEST(ExchangeDeclaration, NoMomentumCoefficientMeansNoMomentumIncrement) {
  core::Scene scene = core::loadScene(SEED_CYLINDER);
  scene.ice.exchange_momentum = 0;
  scene.ice.exchange_heat = 0;
  const FieldUses travel = agree(scene, solidDeclaration(scene), fluidDeclaration(scene));
  EXPECT_EQ(describeUses(travel.of(ExchangePoint::ExchangeIncrements, 0), ExchangePoint::ExchangeIncrements, "steel"),
            "steel: exchange_energy");
  scene.ice.exchange_heat = 1e3;  // heat alone: the energy increment, no momentum increment
  const FieldUses heat = agree(scene, solidDeclaration(scene), fluidDeclaration(scene));
  EXPECT_EQ(describeUses(heat.of(ExchangePoint::ExchangeIncrements, 0), ExchangePoint::ExchangeIncrements, "steel"),
            "steel: exchange_energy");
}

TEST(ExchangeDeclaration, AMismatchNamesThePointAndBothSidesLists) {
  const core::Scene scene = core::loadScene(SEED_CYLINDER);
  ExchangeDeclaration fluid = fluidDeclaration(scene);
  fluid.reads.at[static_cast<std::size_t>(ExchangePoint::SolidState)][0][1] = 3;  // a 3D fluid's velocity
  try {
    agree(scene, solidDeclaration(scene), fluid);
    FAIL() << "a mismatch was accepted";
  } catch (const HandshakeMismatch& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("solid state exchange point"), std::string::npos) << m;
    EXPECT_NE(m.find("the fluid reads steel: mass velocity(3) temperature specific_volume"), std::string::npos) << m;
    EXPECT_NE(m.find("the solid writes steel: mass velocity(2) temperature specific_volume"), std::string::npos) << m;
  }
}

TEST(ExchangeDeclaration, TheTextFormRoundTrips) {
  const core::Scene scene = core::loadScene(FLAP_MPMICE);
  for (const ExchangeDeclaration& d : {solidDeclaration(scene), fluidDeclaration(scene)}) {
    const ExchangeDeclaration back = decodeDeclaration(encodeDeclaration(d));
    EXPECT_EQ(back.reads, d.reads);
    EXPECT_EQ(back.writes, d.writes);
  }
  EXPECT_THROW(decodeDeclaration("1 2"), HandshakeMismatch);
}

}  // namespace
}  // namespace mpmice::coupler

