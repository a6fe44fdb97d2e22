// The surface particles of a solid (src/couplings/surface/solid/surface_particles.h): the outer layer of
// a flap's particles, the same set and order on any number of ranks.
#include <gtest/gtest.h>

#include <cmath>

#include "core/scene/scene.h"
#include "mpm/solver/mpm_solver.h"
#include "couplings/surface/solid/surface_particles.h"
#include "test_comm.h"

using namespace mpmice;

namespace {
core::Scene flap() {
  return core::parseScene(R"(
mesh: {dim: 2, lower: [-0.5, 0], upper: [0.5, 1.2], spacing: [0.025, 0.025]}
time: {end: 1}
materials:
  - {name: flap, kind: solid, density: 3000, model: {type: neo_hookean, youngs_modulus: 4.0e6, poissons_ratio: 0.3}}
  - {name: block, kind: solid, density: 1000, model: {type: linear_elastic, youngs_modulus: 1.0e6, poissons_ratio: 0.3}}
geometry:
  - {shape: {type: box, lo: [-0.05, 0], hi: [0.05, 1]}, material: flap, particles_per_cell: [2, 2]}
  - {shape: {type: box, lo: [0.2, 0.2], hi: [0.3, 0.3]}, material: block, particles_per_cell: [2, 2]}
)", "flap.yaml");
}
}  // namespace

TEST(SurfaceParticles, AreTheOuterLayerOfTheMaterialOnly) {
  const core::Scene s = flap();
  mpm::MpmSolver mpm(s, test::comm());
  const long local = coupler::markSurfaceParticles(mpm, 0);
  // 8 x 80 particles (spacing 0.0125): the perimeter has 2 * 8 + 2 * 80 - 4 = 172.
  EXPECT_EQ(test::comm().sum(static_cast<long long>(local)), 172);
  const auto& p = mpm.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.material[i] != 0) {
      EXPECT_EQ(p.surface[i], 0.0) << "a particle of another material is marked";
      continue;
    }
    const double x = p.x0[0][i], y = p.x0[1][i];
    const double edge = std::min({x + 0.05, 0.05 - x, y, 1.0 - y});  // distance to the flap's outline
    EXPECT_EQ(p.surface[i] != 0.0, edge < 0.0125) << "particle at (" << x << ", " << y << ")";
  }
  const coupler::SurfaceCloud c = coupler::gatherSurfaceCloud(mpm);
  ASSERT_EQ(c.size(), 172u);
  ASSERT_EQ(c.x0.size(), 3u * 172u);
  for (std::size_t k = 1; k < c.size(); ++k) EXPECT_LT(c.ids[k - 1], c.ids[k]) << "ordered by id";
}
