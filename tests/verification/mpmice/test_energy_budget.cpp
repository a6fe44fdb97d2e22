// The energy budget of the coupled MPM-ICE step (docs/coupling.md "Energy budget"): a closed box
// (every face a no-slip wall, no sources), a gas pressure jump and a steel block at rest, 1000
// coupled steps of the monolithic-style schedule (the code path of mpmice and of the MPMD launch):
//  - total energy (kinetic + internal + elastic + solid heat) changes by less than 1e-6 of the
//    mechanical and fluid energy (the solid's heat m cv T left out of the denominator, which would
//    make the bound 200x looser);
//  - the monitor's columns close the balance: total energy less what MPM's own numerics created
//    (particle-grid transfer, stress integration, damping) is constant to round-off (1e-11);
//  - mass is conserved to round-off, and the solid receives exactly the heat the fluid sends.
//  - the stress work is the work the internal forces did on the grid (MpmSolver::addStressWork,
//    mpm.stress_work auto = grid in a coupled run with USL or USF; with MUSL auto is the models'
//    count, the particles deforming with the remapped velocity rather than the nodes' v_L),
//    so the stress integration column stays at round-off (no body force here) in those variants.
// What moves is what the two sides' declarations agree on (as in mpmice and the MPMD launch).
// Variants: linear + USL (FLIP; the default scene: drift < 1e-6, measured 1.4e-11); the same with
// mpm.stress_work material (the models' midpoint stress power: the drift is the named stress
// integration term, and the balance closes); and, where
// MPM's own numerics remove energy the monitor names (FLIP 0.95's and PIC's damping in the
// particle-grid transfer, mpm.damping), B-spline + MUSL with heat exchange (the grid count asked
// for, and auto: the models' count) and GIMP + USF with PIC and damping: their balance closes;
// and no exchange at all (K = H = 0): the solids still take their share of the energy correction
// through the exchange energy, so it must travel (it was not declared then: +1.6e-2 of the scale);
// with K = 0 and 1e3 the steel's heat stays (the gas pays for its own acceleration).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "coupler/transport/in_memory_transport.h"
#include "core/scene/scene.h"
#include "couplings/volume/common/exchange_declaration.h"
#include "couplings/volume/schedule/coupling_schedule.h"
#include "serial_mpi.h"

using namespace mpmice;
using namespace mpmice::coupler;

namespace {

struct Variant {
  const char* name;
  const char* shape;
  const char* update;
  double flip, damping, heat;
  const char* stressWork = "auto";  // mpm.stress_work (auto: grid in a coupled run)
  double momentum = -1;             // ice.exchange_momentum (< 0: the scene's)
};

struct Budget {
  double e0 = 0, e1 = 0, scale = 0, balance0 = 0, balance1 = 0, heat0 = 0;
  double solidMass0 = 0, solidMass1 = 0, fluidMass0 = 0, fluidMass1 = 0;
  bool gridCount = false;  // the count the solver took (MpmSolver::gridStressWork)
  SideTotals solid, fluid;
};

Budget run(const Variant& v, int steps) {
  core::Scene scene = core::loadScene(CLOSED_BOX);
  scene.mpm.shape_function = v.shape;
  scene.mpm.update = v.update;
  scene.mpm.flip = v.flip;
  scene.mpm.damping = v.damping;
  scene.ice.exchange_heat = v.heat;
  if (v.momentum >= 0) scene.ice.exchange_momentum = v.momentum;
  scene.mpm.stress_work = v.stressWork;
  scene.output.enabled = false;
  core::Comm comm{MPI_COMM_SELF};
  mpm::MpmSolver mpm(scene, comm);
  ice::IceSolver ice(scene, comm);
  SolidSide solid(mpm);
  FluidSide fluid(ice, scene);
  // What travels is what the two sides' declarations agree on, as in mpmice and the MPMD launch.
  const FieldUses travel = agree(scene, solidDeclaration(scene), fluidDeclaration(scene));
  const Sides sides{&solid, &fluid, &travel};
  InMemoryTransport tr;
  startCoupling(sides, tr);
  const auto schedule = makeSchedule(scene, comm);
  Budget b;
  b.gridCount = mpm.gridStressWork();
  SideTotals s = solid.totals(), f = fluid.totals();
  b.e0 = s.energy() + f.energy();
  b.scale = s.kinetic + s.internal + f.energy();
  b.balance0 = b.e0 - s.created();
  b.heat0 = s.heat;
  b.solidMass0 = s.mass;
  b.fluidMass0 = f.mass;
  for (int n = 0; n < steps; ++n)
    schedule->step(sides, tr, std::min({solid.stableTimeStep(), fluid.stableTimeStep(), scene.time.dt_max}));
  s = solid.totals();
  f = fluid.totals();
  b.e1 = s.energy() + f.energy();
  b.balance1 = b.e1 - s.created();
  b.solidMass1 = s.mass;
  b.fluidMass1 = f.mass;
  b.solid = s;
  b.fluid = f;
  return b;
}

}  // namespace

TEST(MpmIceEnergyBudget, ClosedBoxSolidAtRestPressureJump1000Steps) {
  const Variant variants[] = {{"linear, USL, FLIP (the scene)", "linear", "usl", 1.0, 0.0, 0.0},
                              {"bspline2, MUSL, FLIP 0.95, heat exchange, stress_work grid", "bspline2", "musl", 0.95,
                               0.0, 1e15, "grid"},
                              {"bspline2, MUSL, FLIP 0.95, heat exchange (auto: material)", "bspline2", "musl", 0.95,
                               0.0, 1e15},
                              {"gimp, USF, PIC, damping 100 1/s", "gimp", "usf", 0.0, 100.0, 0.0},
                              {"linear, USL, FLIP, stress_work material", "linear", "usl", 1.0, 0.0, 0.0, "material"},
                              {"linear, USL, FLIP, no exchange (K = H = 0)", "linear", "usl", 1.0, 0.0, 0.0, "auto", 0.0},
                              {"linear, USL, FLIP, weak exchange (K = 1e3, H = 0)", "linear", "usl", 1.0, 0.0, 0.0, "auto",
                               1e3}};
  for (const Variant& v : variants) {
    const Budget b = run(v, 1000);
    const double drift = (b.e1 - b.e0) / b.scale, closure = (b.balance1 - b.balance0) / b.scale;
    std::printf(
        "  %s: energy drift %.2e of %.6g J (solid heat gained %+.4g J, transfer %+.3g J, stress integration %+.3g J, "
        "damping %+.3g J); balance closes to %.1e; fluid mass %.1e\n",
        v.name, drift, b.scale, b.solid.heat - b.heat0, b.solid.transfer, b.solid.integration, b.solid.damping, closure,
        (b.fluidMass1 - b.fluidMass0) / b.fluidMass0);
    EXPECT_LT(std::abs(closure), 1e-11) << v.name;
    // auto is the grid count in a coupled run except with MUSL (MpmSolver::useGridStressWorkByDefault).
    const bool grid = std::string(v.stressWork) == "grid" ||
                      (std::string(v.stressWork) == "auto" && std::string(v.update) != "musl");
    EXPECT_EQ(b.gridCount, grid) << v.name;
    // The models' midpoint stress power: O(dt^2) a step, named (1.9e-4 J, 5.3e-10 of the scale;
    // before the forces' share of the exchange increments went to the stress work it was 0.455 J,
    // that share counted twice, as heat and in the models' stress power: docs/mpm.md "Stress
    // work"), and apart from the grid count's round-off (below 1e-12 of the scale).
    if (!grid)
      EXPECT_GT(std::abs(b.solid.integration), 1e-10 * b.scale) << v.name;
    else
      EXPECT_LT(std::abs(b.solid.integration), 1e-12 * b.scale) << v.name << ": stress work against the grid's";
    if (&v == &variants[0]) {
      EXPECT_LT(std::abs(drift), 1e-6) << v.name;
    }
    // Where the solid holds no fluid (K = 0) the gas pays for its own acceleration, not the
    // solid's heat: measured -221 J (what the gas's traces inside the steel cannot take), 6.1e-4
    // of the scale; by heat capacity the steel gave the gas 6948 J (1.9e-2), docs/coupling.md
    // "Energy budget". (With K = 1e3 the drag's heat of the gas's slip through the steel is
    // shared by heat capacity: the steel gains +1232 J, and the balance closes.)
    if (v.momentum == 0) {
      EXPECT_LT(std::abs(b.solid.heat - b.heat0), 1e-3 * b.scale) << v.name;
    }
    // Whatever MPM's numerics created, the exchanges created nothing: the drift is those terms.
    EXPECT_LT(std::abs(drift - b.solid.created() / b.scale), 1e-11) << v.name;
    EXPECT_EQ(b.solidMass1, b.solidMass0) << v.name;
    EXPECT_LT(std::abs(b.fluidMass1 - b.fluidMass0), 1e-13 * b.fluidMass0) << v.name;
    // The gas did move and heat the solid: the test is not of a state at rest.
    EXPECT_GT(b.fluid.kinetic, 1e-4 * b.scale) << v.name;
    EXPECT_GT(b.solid.kinetic, 0.0) << v.name;
  }
}
