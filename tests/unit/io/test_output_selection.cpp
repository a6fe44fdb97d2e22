// output.fields (src/core/io/output_selection.h): whole names, per-material names for every
// material, positions always, and a standalone program's refusal of a name it does not offer.
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/io/output_selection.h"

namespace mpmice::core {
namespace {

const std::vector<std::string> kMaterials{"air", "water"};

TEST(OutputSelection, AnEmptyListSelectsEverything) {
  EXPECT_TRUE(outputSelected({}, "pressure"));
  EXPECT_TRUE(outputSelected({}, "air_velocity", kMaterials));
}

TEST(OutputSelection, APerMaterialNameSelectsItForEveryMaterial) {
  const std::vector<std::string> w{"velocity", "pressure"};
  EXPECT_TRUE(outputSelected(w, "pressure", kMaterials));
  EXPECT_TRUE(outputSelected(w, "air_velocity", kMaterials));
  EXPECT_TRUE(outputSelected(w, "water_velocity", kMaterials));
  EXPECT_FALSE(outputSelected(w, "air_density", kMaterials));
  EXPECT_FALSE(outputSelected(w, "pressure_iterations", kMaterials));
  EXPECT_TRUE(outputSelected({"air_density"}, "air_density", kMaterials));
  EXPECT_FALSE(outputSelected({"air_density"}, "water_density", kMaterials));
}

TEST(OutputSelection, FieldsAndParticleArraysAreFiltered) {
  const Box b{{0, 0, 0}, {1, 0, 0}};
  std::vector<Field> all;
  for (const char* n : {"pressure", "air_density", "air_velocity"}) all.emplace_back(n, Centering::Cell, b, 1, 0);
  const auto kept = selectFields(std::move(all), {"velocity"}, kMaterials);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].name(), "air_velocity");

  const std::vector<double> v{1, 2};
  ParticleOutput p;
  p.count = 2;
  p.addScalar("mass", v).addScalar("volume", v);
  p.addVector("stress", {std::span<const double>(v), std::span<const double>(v)});
  const auto q = selectParticles(p, {"stress", "pressure"});
  EXPECT_TRUE(q.scalars.empty());
  ASSERT_EQ(q.vectors.size(), 1u);
  EXPECT_EQ(q.vectors[0].name, "stress");
  EXPECT_EQ(q.count, 2);
}

TEST(OutputSelection, AStandaloneProgramRefusesANameItDoesNotOffer) {
  const std::vector<std::string> offered{"pressure", "air_density", "air_velocity"};
  EXPECT_NO_THROW(checkOutputFields({"pressure", "velocity"}, offered, kMaterials, "ice_solver"));
  try {
    checkOutputFields({"pressure", "stres"}, offered, kMaterials, "ice_solver");
    FAIL() << "an unknown field was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("output.fields: ice_solver offers no field 'stres'"), std::string::npos) << m;
    EXPECT_NE(m.find("valid names: pressure, air_density, air_velocity"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace mpmice::core
