// advance() runs the step in fewer particle passes than its phases (USL / MUSL: particle-to-grid
// and internal forces in one pass; the next step's CFL signal speed taken in the stress pass).
// Same operations in the same order: the results must be those of the phases, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/parallel/comm.h"
#include "mpm_problems.h"
#include "serial_mpi.h"

using namespace mpmice;
using namespace mpmice::mpm;
namespace pr = mpmice::mpm::problems;

namespace {

core::Comm self() { return core::Comm(MPI_COMM_SELF); }

// The colliding disks under gravity (body force in the force pass), in 2D or 3D.
core::Scene disks(int dim, const std::string& shape, const std::string& update) {
  auto s = pr::disksScene(16, update, 0.95, shape);
  s.gravity = {0.5, -9.81, dim == 3 ? 1.5 : 0.0};
  if (dim == 3) {
    const double h = 1.0 / 16;
    s.mesh = core::Mesh(3, {0, 0, 0}, {h, h, h}, {16, 16, 16});
    for (auto& r : s.geometry) {
      r.shape.center[2] = 0.5;
      r.particles_per_cell = {2, 2, 2};
      r.velocity[2] = 0.05;
    }
  }
  return s;
}

// One step by the public phases, the time step computed afresh from the particles.
void stepByPhases(MpmSolver& s) {
  (void)s.particles();  // written from outside: any value kept from the last step is dropped
  s.beginStep(s.stableTimeStep());
  s.particlesToGrid();
  s.computeInternalForces();
  s.updateGrid();
  s.gridToParticles();
  s.endStep();
}

void expectSameBits(const ParticleSet& a, const ParticleSet& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int d = 0; d < 3; ++d) {
      ASSERT_EQ(a.x[d][i], b.x[d][i]) << what << " x" << d << " particle " << i;
      ASSERT_EQ(a.v[d][i], b.v[d][i]) << what << " v" << d << " particle " << i;
    }
    // Every stored component (in 1D / 2D the out-of-plane ones are not stored: ParticleLayout).
    for (int k = 0; k < 9; ++k) {
      if (a.stored(a.F[k])) {
        ASSERT_EQ(a.F[k][i], b.F[k][i]) << what << " F" << k << " particle " << i;
      }
    }
    for (int k = 0; k < 6; ++k) {
      if (a.stored(a.stress[k])) {
        ASSERT_EQ(a.stress[k][i], b.stress[k][i]) << what << " stress" << k << " particle " << i;
      }
    }
    ASSERT_EQ(a.vol[i], b.vol[i]) << what << " volume, particle " << i;
    ASSERT_EQ(a.work[i], b.work[i]) << what << " work, particle " << i;
  }
}

}  // namespace

TEST(StepPasses, AdvanceGivesThePhasesResultsBitForBit) {
  struct Case {
    int dim;
    const char* shape;
    const char* update;
  };
  const Case cases[] = {{2, "linear", "usl"}, {2, "linear", "musl"},   {2, "bspline2", "usl"}, {2, "gimp", "musl"},
                        {2, "bspline3", "usf"}, {3, "linear", "usl"}, {3, "bspline2", "musl"}};
  for (const auto& c : cases) {
    const std::string what = std::to_string(c.dim) + "D " + c.shape + " " + c.update;
    const auto scene = disks(c.dim, c.shape, c.update);
    MpmSolver fused(scene, self()), phases(scene, self());
    for (int step = 0; step < 25; ++step) {  // past a re-sort (every 20 steps)
      const double dt = fused.advance();
      stepByPhases(phases);
      ASSERT_EQ(fused.time(), phases.time()) << what << " step " << step << " (dt " << dt << ")";
    }
    expectSameBits(fused.particles(), phases.particles(), what);
    // The grids of the last step too (mass, velocity and force of every node).
    const auto& ga = fused.grid();
    const auto& gb = phases.grid();
    for (std::int64_t k = 0; k < ga.numNodes(); ++k) {
      ASSERT_EQ(ga.mass.data()[k], gb.mass.data()[k]) << what << " node " << k;
      for (int d = 0; d < c.dim; ++d) {
        ASSERT_EQ(ga.velocity.data(d)[k], gb.velocity.data(d)[k]) << what << " node " << k;
        ASSERT_EQ(ga.force.data(d)[k], gb.force.data(d)[k]) << what << " node " << k;
      }
    }
  }
}

TEST(StepPasses, TheSignalSpeedKeptFromTheStepIsDroppedWhenTheParticlesAreWritten) {
  MpmSolver solver(disks(2, "linear", "usl"), self());
  solver.advance();
  const double kept = solver.stableTimeStep();
  // A particle made 100x faster than the wave speed: the time step must follow at once.
  solver.particles().v[0][0] = 100.0 * solver.model(0).waveSpeed(1000.0);
  const double after = solver.stableTimeStep();
  EXPECT_LT(after, 0.02 * kept);
}
