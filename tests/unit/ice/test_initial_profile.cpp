// A geometry object's linear initial velocity (velocity_gradient, issue 14): every mesh samples the
// same field u(x) = velocity + G (x - velocity_origin) at its cell centres, which is the cell mean
// of a linear field, so the fluid's momentum is the field's integral on any mesh; the piston's
// quasi-static start is therefore one scene for every resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/scene/scene.h"
#include "ice/solver/ice_solver.h"
#include "test_comm.h"

using namespace mpmice;

namespace {

// The piston's gas (configs/piston.yaml) without the piston: u = 50 x on [0, 0.2], u = 10 - 25
// (x - 0.6) on [0.6, 1], still gas between.
core::Scene gasAt(int cells) {
  return core::parseScene(R"(
mesh: {dim: 1, lower: [0], upper: [1], cells: [)" + std::to_string(cells) + R"(]}
time: {end: 1}
materials:
  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}, specific_heat: 717.5}
geometry:
  - {name: still, shape: {type: box, lo: [0], hi: [1]}, material: air, pressure: 101325}
  - {name: behind, shape: {type: box, lo: [0], hi: [0.2]}, material: air, pressure: 101325,
     velocity: [0], velocity_gradient: [[50]]}
  - {name: ahead, shape: {type: box, lo: [0.6], hi: [1]}, material: air, pressure: 101325,
     velocity: [10], velocity_origin: [0.6], velocity_gradient: [[-25]]}
boundary: {x-: slip_wall, x+: slip_wall}
)",
                          "profile.yaml");
}

double exactU(double x) { return x <= 0.2 ? 50 * x : x >= 0.6 ? 10 - 25 * (x - 0.6) : 0.0; }

}  // namespace

TEST(IceInitialProfile, EveryMeshSamplesTheLinearVelocityAtItsCellCentres) {
  for (const int n : {5, 25, 50, 100, 200}) {
    const core::Scene s = gasAt(n);
    ice::IceSolver sol(s, test::comm());
    const core::Mesh& mesh = sol.mesh();
    double momentum = 0, worst = 0;
    core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
      const double x = mesh.cellCenter(0, i), u = sol.state().mat[0].vel(i, j, k, 0);
      worst = std::max(worst, std::abs(u - exactU(x)));
      momentum += sol.state().mat[0].mass(i, j, k) * u;
    });
    EXPECT_LT(worst, 1e-12) << n << " cells";
    // The integral of rho u over the two gas columns: rho (50 x 0.2^2 / 2 + 10 x 0.4 / 2) = 3 rho.
    const double rho = 101325 / (0.4 * 717.5 * 300);
    EXPECT_NEAR(momentum / (3 * rho), 1.0, 1e-12) << n << " cells";
  }
}

TEST(IceInitialProfile, WithoutAGradientTheVelocityIsUniformToTheBit) {
  core::Scene s = gasAt(10);
  s.geometry.resize(1);
  s.geometry[0].velocity = {1.0 / 3.0, 0, 0};
  ice::IceSolver sol(s, test::comm());
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) { EXPECT_EQ(sol.state().mat[0].vel(i, j, k, 0), 1.0 / 3.0); });
}
