// A solid touching `free` / `outflow` mesh faces in the coupled step (docs/coupling.md "Open
// faces"), on the Stokes plate (configs/stokes_plate.yaml): a steel plate on 0 <= x <= 0.1 and air
// beside it in a strip along y whose y faces are open.
//  - At rest, two cells tall at dx 0.0025 (free and outflow faces, GIMP and linear): the plate
//    stays at rest. The mean-stress correction's boundary term on the open faces' nodes, which ICE's
//    zero-gradient pressure does not balance, grew it from round-off to 1e-3 m/s in 0.4 ms.
//  - Stokes' first problem at half the scene's spacing with the strip two cells tall (the scene's
//    height): it runs to the scene's end (before the fix the plate's boundary rows, moving along y,
//    opened a gap ICE filled by expanding the steel, and a rarefied trace of air in a plate cell
//    collapsed the time step at 0.1 ms), the two rows agree, and the error falls from the scene's
//    spacing (one cell tall) at first order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "coupled_run.h"
#include "serial_mpi.h"

namespace mpmice::test {
namespace {

/// The Stokes scene at spacing dx over `rows` cells of the strip's height, the gas at velocity
/// `u` along y, y faces of type `open`.
core::Scene stripScene(double dx, int rows, double u, core::BoundaryType open, const std::string& shape) {
  core::Scene s = core::loadScene(STOKES_SCENE);
  const core::RealVect o = s.mesh.origin();
  const int n = static_cast<int>(std::lround((s.mesh.upper(0) - o[0]) / dx));
  s.mesh = core::Mesh(2, o, {dx, dx, 1}, {n, rows, 1});
  for (auto& r : s.geometry) {
    r.shape.hi[1] = o[1] + rows * dx;
    if (r.fill.front().material == "air") r.velocity[1] = u;
  }
  s.boundary[2].type = s.boundary[3].type = open;
  s.mpm.shape_function = shape;
  return s;
}

double maxParticleSpeed(const CoupledRun& run) {
  const auto& p = run.mpm.particles();
  double v = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < 3; ++d) v = std::max(v, std::abs(p.v[d][i]));
  return v;
}

}  // namespace

TEST(OpenFaces, PlateAtRestBetweenOpenFacesStaysAtRest) {
  struct Case {
    core::BoundaryType open;
    const char* shape;
  };
  for (const Case c : {Case{core::BoundaryType::Free, "gimp"}, Case{core::BoundaryType::Outflow, "linear"}}) {
    CoupledRun run(stripScene(0.0025, 2, 0.0, c.open, c.shape));
    double worst = 0;
    run.runTo(4.0e-4, [&] { worst = std::max(worst, maxParticleSpeed(run)); });
    std::printf("plate at rest, %s, %s faces: max particle speed over 0.4 ms %.3e m/s (%ld steps)\n", c.shape,
                c.open == core::BoundaryType::Free ? "free" : "outflow", worst, run.steps);
    EXPECT_LT(worst, 1e-9) << c.shape;
  }
}

// With coupling.solid_transport mpm (the solids' face transport, src/ice/face/solid_faces.h) an
// open face carries the boundary cell's solid: the plate at rest stays at rest (with no cover there
// the fluids' share was scaled up to the whole face, and the plate's speed grew from round-off to
// 1.8e-9 m/s in 0.4 ms), and with the gas sliding along it the plate moves as with ICE's transport
// (the drag; before, it grew to 6.5 times that).
TEST(OpenFaces, SolidTransportCarriesTheBoundaryCellsSolidThroughOpenFaces) {
  auto run = [](double u, core::BoundaryType open, const std::string& transport) {
    core::Scene sc = stripScene(0.0025, 2, u, open, "gimp");
    sc.coupling.solid_transport = transport;
    CoupledRun r(sc);
    double worst = 0;
    r.runTo(4.0e-4, [&] { worst = std::max(worst, maxParticleSpeed(r)); });
    return worst;
  };
  const double rest = run(0.0, core::BoundaryType::Free, "mpm");
  const double dragIce = run(1.0, core::BoundaryType::Outflow, "ice");
  const double dragMpm = run(1.0, core::BoundaryType::Outflow, "mpm");
  std::printf("solid_transport mpm: plate at rest between free faces, max particle speed over 0.4 ms %.3e m/s; "
              "gas at 1 m/s along it (outflow faces): %.3e m/s (ice transport %.3e m/s)\n",
              rest, dragMpm, dragIce);
  EXPECT_LT(rest, 1e-9);
  EXPECT_GT(dragIce, 0.0);
  EXPECT_LT(dragMpm, 1.5 * dragIce);
  EXPECT_GT(dragMpm, dragIce / 1.5);
}

TEST(OpenFaces, StokesPlateTwoCellsTallAtHalfTheSpacing) {
  const core::Scene scene = core::loadScene(STOKES_SCENE);
  const double dx0 = scene.mesh.spacing()[0], U = 1.0;
  const int rows0 = static_cast<int>(std::lround((scene.mesh.upper(1) - scene.mesh.origin()[1]) / dx0));
  ASSERT_EQ(rows0, 1) << "the scene's strip is one cell tall";
  const double nu = 4.0;  // the scene's mu / rho (its header), checked against the gas below
  std::vector<double> dxs = {dx0, dx0 / 2}, errors;
  for (double dx : dxs) {
    const int rows = static_cast<int>(std::lround(dx0 / dx));  // the scene's height
    CoupledRun run(stripScene(dx, rows, U, scene.boundary[2].type, scene.mpm.shape_function));
    const core::Scene& s = run.scene;
    run.runTo(s.time.end);
    const int air = s.materialIndex("air");
    const auto& gas = run.ice.state().mat[static_cast<std::size_t>(air)];
    double surface = 0;
    for (const auto& r : s.geometry)
      if (r.fill.front().material == "steel") surface = r.shape.hi[0];
    const core::MaterialSpec& ms = s.materials[static_cast<std::size_t>(air)];
    const double R = (ms.eos.get("gamma", 1.4) - 1) * ms.specific_heat;
    double p0 = 0, T0 = 0;
    for (const auto& r : s.geometry)
      if (r.fill.front().material == "air") p0 = *r.pressure, T0 = r.temperature;
    ASSERT_NEAR(ms.viscosity / (p0 / (R * T0)), nu, 0.01 * nu);
    const double t = run.time();
    double err = 0, rowDiff = 0;
    const core::Box& b = run.ice.ownedBox();
    for (int i = b.lo[0]; i <= b.hi[0]; ++i) {
      const double x = s.mesh.cellCenter(0, i);
      if (x < surface) continue;
      const double exact = U * std::erf((x - surface) / (2 * std::sqrt(ms.viscosity / (p0 / (R * T0)) * t)));
      for (int j = b.lo[1]; j <= b.hi[1]; ++j) {
        err = std::max(err, std::abs(gas.vel(i, j, 0, 1) - exact) / U);
        rowDiff = std::max(rowDiff, std::abs(gas.vel(i, j, 0, 1) - gas.vel(i, b.lo[1], 0, 1)) / U);
      }
    }
    errors.push_back(err);
    std::printf("stokes dx %.4g, %d rows: t = %.4g s in %ld steps, max |u - exact| / U = %.4e, rows differ by %.2e U, "
                "max particle speed %.3e m/s\n",
                dx, rows, t, run.steps, err, rowDiff, maxParticleSpeed(run));
    EXPECT_NEAR(t, s.time.end, 1e-12 * s.time.end);
    EXPECT_LT(rowDiff, 1e-5) << "dx " << dx;
  }
  const double order = observedOrder(dxs, errors);
  std::printf("stokes fitted order (one row at dx, two at dx / 2) %.3f\n", order);
  EXPECT_LT(errors[1], errors[0]);
  EXPECT_GT(order, 0.8);
}

}  // namespace mpmice::test
