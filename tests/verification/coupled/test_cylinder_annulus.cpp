// The seed cylinder's accuracy is not tied to its own radii and pressure (issue 14): the shipped
// scene (configs/pressurized_cylinder.yaml, its settings as they are) and another annulus made
// from it - other radii (0.3 .. 0.6 m instead of 0.5 .. 1.0), another inner pressure (10 MPa
// instead of 19.4) - both at 10 cells across the wall, run through the coupling to the scene's
// end. The Eq. 13 error of each against the exact Lame sum (src/study/reference/lame_cylinder.h:
// r_i, r_o, p_amb and p_ref from the scene, P the mean pressure inside 0.8 r_i) is asserted, and
// the other annulus's error must be of the same size as the seed's: within a factor 1.15 either way,
// and the seed's at most 1.3 x MPM alone's with the same shape function and particles per cell
// (the Lame annulus loaded on its inner particle layer, tests/verification/mpm/mpm_problems.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "coupled_run.h"
#include "mpm_problems.h"
#include "mpm/particles/particle_set.h"
#include "serial_mpi.h"
#include "study/reference/lame_cylinder.h"

namespace mpmice::test {
namespace {

constexpr int kCellsAcrossTheWall = 10;
// Measured (2026-12-02, bspline2 4x4 as shipped): seed 0.0361, other annulus 0.0362 (ratio 1.003)
// with the energy source's power shared by the cells' volume inside its shape; before that 0.0510
// and 0.0511, and before the surface-normal mean-stress excess and the particle-weighted cell
// forces 0.0759 and 0.0761. With 10 atm outside the other annulus gives 0.0564 (was 0.0736, 0.1081):
// the exact sum itself is 37 % lower there; in stress 0.98 x (the test below).
constexpr double kOtherAmbient = 101325;
constexpr double kSameSize = 1.15;  // the other annulus's error within this factor of the seed's
constexpr double kSeedErrorBound = 0.040;  // the shipped settings at dx 0.05: 0.0361 measured (0.0510, 0.0759 before)
// Issue 14: the coupled error at most this multiple of MPM alone's with the same settings. Measured
// (2026-12-02, docs/coupling.md): 0.80 at dx 0.05 (0.0361 against 0.0450), 0.91 at 0.025, 1.01 at 0.0125.
constexpr double kCoupledOverMpmAlone = 1.3;

/// The shipped scene with the annulus r_i .. r_o (the mesh 1.2 r_o wide, as the seed's), spacing
/// (r_o - r_i) / 10, and the source's power set to heat the inside air to about P over its
/// interval (the wall's expansion ignored, as the scene's comment does).
core::Scene annulusScene(double ri, double ro, double P, double ambient) {
  core::Scene s = core::loadScene(CYLINDER_SCENE);
  const double L = 1.2 * ro, dx = (ro - ri) / kCellsAcrossTheWall;
  const int n = static_cast<int>(std::lround(L / dx));
  s.mesh = core::Mesh(2, s.mesh.origin(), {dx, dx, 1}, {n, n, 1});
  const auto setAnnulus = [&](core::ShapeSpec& a) {
    a.inner_radius = ri;
    a.outer_radius = ro;
  };
  double p0 = 0, gamma = 1.4;
  for (auto& r : s.geometry) {
    if (r.shape.type == "annulus") setAnnulus(r.shape);
    if (r.shape.type == "difference") {
      r.shape.children.at(0).hi = {L, L, 0};
      setAnnulus(r.shape.children.at(1));
      r.pressure = ambient;
      p0 = ambient;
      gamma = s.material(r.fill.at(0).material)->eos.get("gamma", 1.4);
    }
  }
  for (auto& b : s.boundary)
    if (b.pressure) b.pressure = ambient;
  for (auto& src : s.sources) {
    src.shape.radius = ri;
    src.power_density = (P - p0) / (gamma - 1) / (src.end - src.start);
  }
  return s;
}

struct AnnulusError {
  double error = 0, P = 0, sum = 0;  // Eq. 13 (relative to the exact sum), inner pressure, exact sum [Pa]
  [[nodiscard]] double stressError() const { return error * sum; }  // mean |(s_r + s_t) - S| [Pa]
};

/// Runs the scene to its end and measures Eq. 13 as cylinder_lame does.
AnnulusError runAnnulus(const core::Scene& scene, const char* label) {
  const study::Annulus a = study::annulusOf(scene, label);
  CoupledRun run(scene);
  run.runTo(scene.time.end);
  const core::Mesh& mesh = run.scene.mesh;
  const core::Box& b = run.ice.ownedBox();
  double psum = 0;
  int pn = 0;
  for (int j = b.lo[1]; j <= b.hi[1]; ++j)
    for (int i = b.lo[0]; i <= b.hi[0]; ++i)
      if (std::hypot(mesh.cellCenter(0, i), mesh.cellCenter(1, j)) < 0.8 * a.ri) {
        psum += run.ice.pressure()(i, j, 0);
        ++pn;
      }
  EXPECT_GT(pn, 0);
  AnnulusError out;
  out.P = psum / pn;
  const double S = study::lameSum(a, out.P);
  out.sum = S;
  const auto& p = run.mpm.particles();
  double err = 0;
  for (std::size_t q = 0; q < p.size(); ++q) err += std::abs(p.stress[mpm::kXX][q] + p.stress[mpm::kYY][q] - S) / S;
  out.error = err / double(p.size());
  std::printf("%s: r %.3g .. %.3g m, dx %.4g m, %zu particles, %ld steps, P = %.4g Pa, Eq. 13 error %.4f (of the "
              "exact sum %.4g Pa: %.4g Pa)\n", label, a.ri, a.ro, mesh.dx(0), p.size(), run.steps, out.P, out.error, S,
              out.stressError());
  return out;
}

TEST(CylinderAnnulus, AnotherAnnulusHasTheSeedsErrorAtTheSameCellsAcrossTheWall) {
  const AnnulusError seed = runAnnulus(annulusScene(0.5, 1.0, 19.4e6, 101325), "seed annulus");
  const AnnulusError other = runAnnulus(annulusScene(0.3, 0.6, 10.0e6, kOtherAmbient), "other annulus");
  EXPECT_NEAR(other.P, 10.0e6, 0.05 * 10.0e6) << "the source heats the inside air to about 10 MPa";
  EXPECT_LT(seed.error, kSeedErrorBound) << "the seed at 10 cells across the wall";
  EXPECT_LT(other.error, kSameSize * seed.error);
  EXPECT_GT(other.error, seed.error / kSameSize);
  // MPM alone on the seed's annulus at the same spacing, shape function and particles per cell.
  const core::Scene shipped = core::loadScene(CYLINDER_SCENE);
  int ppc = 0;
  for (const auto& r : shipped.geometry)
    if (r.shape.type == "annulus") ppc = r.particles_per_cell[0];
  ASSERT_GT(ppc, 0) << "the wall's particles per cell";
  const double dx = 0.5 / kCellsAcrossTheWall;
  const double alone = mpm::problems::runLame(mpm::problems::lameScene(dx, shipped.mpm.shape_function, 1.0e-3, 4.0e-3,
                                                                       1.0e4, ppc), core::Comm(MPI_COMM_SELF)).error;
  std::printf("MPM alone (%s, %d x %d particles per cell, dx %.4g m): Eq. 13 error %.4f; coupled / alone %.3f\n",
              shipped.mpm.shape_function.c_str(), ppc, ppc, dx, alone, seed.error / alone);
  EXPECT_LT(seed.error, kCoupledOverMpmAlone * alone) << "issue 14: coupled at most 1.3 x MPM alone";
}

// The ambient pressure adds no error of its own: the other annulus with 10 atm of air outside (the
// solid still stress-free at 1 atm; the reference's p_amb term) against the same annulus at 1 atm.
// Compared in Pa (mean |(s_r + s_t) - S|): 10 atm outside lowers the exact sum S itself by 37 %
// (6.60 -> 4.16 MPa), so Eq. 13, relative to S, grows by 1/0.63 for the same stress error. Measured
// (2026-12-02): 1 atm 0.0511 of 6.597 MPa = 0.337 MPa, 10 atm 0.0736 of 4.165 MPa = 0.307 MPa (0.91 x).
TEST(CylinderAnnulus, TenAtmospheresOutsideAddNoStressError) {
  const AnnulusError one = runAnnulus(annulusScene(0.3, 0.6, 10.0e6, 101325), "other annulus, 1 atm outside");
  const AnnulusError ten = runAnnulus(annulusScene(0.3, 0.6, 10.0e6, 10 * 101325.0), "other annulus, 10 atm outside");
  EXPECT_LT(ten.sum, 0.7 * one.sum) << "the ambient term of the exact reference";
  EXPECT_LT(ten.stressError(), kSameSize * one.stressError());
}

}  // namespace
}  // namespace mpmice::test
