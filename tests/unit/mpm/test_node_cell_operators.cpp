// The MPM-ICE node-cell operators (mpm/cell/node_cell_operators.h): the node-to-cell average and
// its transpose, uniform fields, the absent-solid state and the step stamp of per-step data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>
#include <string>

#include "core/parallel/comm.h"
#include "mpm/cell/node_cell_operators.h"
#include "mpm/mpm_constants.h"
#include "mpm/solver/mpm_solver.h"
#include "mpm_problems.h"
#include "serial_mpi.h"

using namespace mpmice;
using namespace mpmice::mpm;
namespace pr = mpmice::mpm::problems;

namespace {

constexpr double kRho = 1000;

// A solid block inside a 2D or 3D mesh of 8^dim cells of 0.25 (walls all round): the block covers
// some cells and leaves the others empty.
core::Scene scene(int dim) {
  core::Scene s;
  s.mesh = core::Mesh(dim, {0, 0, 0}, {0.25, 0.25, 0.25}, {8, 8, dim == 3 ? 8 : 1});
  for (auto& f : s.boundary) f.type = core::BoundaryType::NoSlipWall;
  s.materials = {pr::solid("block", kRho, pr::elastic("linear_elastic", 1e6, 0.25))};
  core::ShapeSpec box;
  box.type = "box";
  box.lo = {0.5, 0.5, dim == 3 ? 0.5 : 0.0};
  box.hi = {1.25, 1.0, dim == 3 ? 1.0 : 0.0};
  s.geometry = {pr::region("block", box, "block", {2, 2, dim == 3 ? 2 : 1})};
  return s;
}

core::Comm self() { return core::Comm(MPI_COMM_SELF); }

constexpr double kU[3] = {0.3, -0.2, 0.1};

// A solver after particle-to-grid with every particle at velocity kU and temperature 350 K.
void start(MpmSolver& solver) {
  auto& p = solver.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int d = 0; d < solver.scene().mesh.dim(); ++d) p.v[d][i] = kU[d];
    p.temperature[i] = 350.0;
  }
  solver.beginStep(solver.stableTimeStep());
  solver.particlesToGrid();
}

double sum(const core::Field& f, int comp = 0) {
  double s = 0;
  core::forEach(f.box(), [&](int i, int j, int k) { s += f(i, j, k, comp); });
  return s;
}

// After the grid update: a momentum increment of (0.2, -0.1) times its mass in one cell of the
// block (3, 2[, 2]), applied (applyCellMomentumIncrement); what the cell's view charged for it,
// dp . (u_L + dv / 2), and the node velocities before it. Checks that the kinetic deficit is zero
// in every other cell.
struct CellIncrement {
  int i, j, k;
  double gain = 0;
  core::Field vOld;
};
CellIncrement applyCellIncrement(MpmSolver& solver) {
  const int dim = solver.scene().mesh.dim();
  NodeCellOperators& ops = solver.cells();
  const SolidCellState& cs = ops.cellState(0);
  core::Field pL("pL", core::Centering::Cell, cs.mass.box(), 3, 0, 0.0);
  ops.cellLagrangianMomentum(0, pL);
  CellIncrement c{3, 2, dim == 3 ? 2 : 0, 0.0, solver.grid().velocityL};
  core::Field dp("dp", core::Centering::Cell, cs.mass.box(), 3, 0, 0.0);
  const double m = cs.mass(c.i, c.j, c.k);
  dp(c.i, c.j, c.k, 0) = 0.2 * m;
  dp(c.i, c.j, c.k, 1) = -0.1 * m;
  ops.applyCellMomentumIncrement(0, dp);
  for (int d = 0; d < dim; ++d) {
    const double p = dp(c.i, c.j, c.k, d);
    c.gain += p * (pL(c.i, c.j, c.k, d) / m + 0.5 * p / m);
  }
  const core::Field& def = ops.kineticDeficit(0);
  core::forEach(def.box(), [&](int i, int j, int k) {
    if (i != c.i || j != c.j || k != c.k) {
      EXPECT_EQ(def(i, j, k), 0.0) << dim << " cell " << i << "," << j << "," << k;
    }
  });
  return c;
}

}  // namespace

// Every node's value is shared out completely among the mesh cells around it.
TEST(NodeCellOperators, NodeSharesSumToOne) {
  for (int dim : {1, 2, 3}) {
    const core::Mesh mesh(dim, {0, 0, 0}, {1, 1, 1}, {3, dim > 1 ? 4 : 1, dim > 2 ? 2 : 1});
    core::Field total("total", core::Centering::Node, mesh.nodeBox(), 1, 0, 0.0);
    core::forEach(mesh.cellBox(), [&](int i, int j, int k) {
      int corners = 0;
      forCellNodes(mesh, i, j, k, [&](int ni, int nj, int nk, double share) {
        total(ni, nj, nk) += share;
        ++corners;
      });
      EXPECT_EQ(corners, 1 << dim);
    });
    core::forEach(mesh.nodeBox(), [&](int i, int j, int k) { EXPECT_DOUBLE_EQ(total(i, j, k), 1.0) << dim; });
  }
}

TEST(NodeCellOperators, CellOfParticleIsClamped) {
  const core::Mesh mesh(2, {0, 0, 0}, {0.5, 0.25, 1}, {4, 4, 1});
  ParticleSet p;
  p.resize(2);
  p.x[0][0] = 1.2;
  p.x[1][0] = 0.3;
  p.x[0][1] = -0.1;
  p.x[1][1] = 5.0;
  const auto c0 = cellOfParticle(mesh, p, 0, mesh.cellBox());
  EXPECT_EQ(c0[0], 2);
  EXPECT_EQ(c0[1], 1);
  EXPECT_EQ(c0[2], 0);
  const auto c1 = cellOfParticle(mesh, p, 1, mesh.cellBox());
  EXPECT_EQ(c1[0], 0);
  EXPECT_EQ(c1[1], 3);
  EXPECT_EQ(cellCoordinate(mesh, 0, -0.1), -1);
}

// A uniform particle state maps to itself in every cell the solid reaches; the others hold the
// absent-solid state.
TEST(NodeCellOperators, UniformStateMapsToItselfAndEmptyCellsAreAbsent) {
  for (int dim : {2, 3}) {
    MpmSolver solver(scene(dim), self());
    start(solver);
    const SolidCellState& cs = solver.cells().cellState(0);
    double particleMass = 0;
    for (double m : solver.particles().mass) particleMass += m;
    EXPECT_NEAR(sum(cs.mass), particleMass, 1e-12 * particleMass) << dim;
    int full = 0, empty = 0;
    core::forEach(cs.mass.box(), [&](int i, int j, int k) {
      if (cs.mass(i, j, k) > 0) {
        ++full;
        for (int d = 0; d < dim; ++d) EXPECT_NEAR(cs.velocity(i, j, k, d), kU[d], 1e-12);
        EXPECT_NEAR(cs.temperature(i, j, k), 350.0, 1e-9);
        EXPECT_NEAR(cs.specificVolume(i, j, k), cs.volume(i, j, k) / cs.mass(i, j, k), 1e-15);
      } else {
        ++empty;
        for (int d = 0; d < 3; ++d) EXPECT_EQ(cs.velocity(i, j, k, d), 0.0);
        EXPECT_EQ(cs.specificVolume(i, j, k), 1.0 / kRho);
        EXPECT_EQ(cs.temperature(i, j, k), kReferenceTemperature);
      }
    });
    EXPECT_GT(full, 0);
    EXPECT_GT(empty, 0);
    EXPECT_EQ(cs.stamp, solver.cells().generation());
  }
}

// addCellForce spreads a cell quantity through the particles in the cell (mass shares, each with
// its own shape function): it is the transpose of the particle-to-cell sum, so the particles' cell
// mass times u goes to m_n u at every node, and the spread total is the cell total.
TEST(NodeCellOperators, TransposeIsAdjointOfTheParticleToCellSum) {
  for (int dim : {2, 3}) {
    MpmSolver solver(scene(dim), self());
    start(solver);
    NodeCellOperators& ops = solver.cells();
    const SolidCellState& cs = ops.cellState(0);
    core::Field force("force", core::Centering::Cell, cs.mass.box(), 3, 0, 0.0);
    const ParticleSet& ps = solver.particles();
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const auto c = cellOfParticle(solver.scene().mesh, ps, i, force.box());
      for (int d = 0; d < 3; ++d) force(c[0], c[1], c[2], d) += ps.mass[i] * kU[d];
    }
    ops.addCellForce(0, force);
    const Grid& g = solver.grid();
    const core::Field& fe = g.externalForce;
    // Owned nodes only (the grid box has a ghost layer).
    const core::Box nodes = solver.scene().mesh.nodeBox();
    double spread[3] = {0, 0, 0}, cellTotal[3] = {0, 0, 0};
    core::forEach(nodes, [&](int i, int j, int k) {
      for (int d = 0; d < dim; ++d) {
        spread[d] += fe(i, j, k, d);
        EXPECT_NEAR(fe(i, j, k, d), g.mass(i, j, k) * kU[d], 1e-12 * (1 + g.mass(i, j, k)));
      }
    });
    for (int d = 0; d < dim; ++d) {
      cellTotal[d] = sum(force, d);
      EXPECT_NEAR(spread[d], cellTotal[d], 1e-12 * std::abs(cellTotal[d])) << dim << " " << d;
    }
    // And back: the node-to-cell average of m_n u (cellLagrangianMomentum of v_L = u) is m_c u.
    solver.updateGrid();
    Grid& gm = solver.grid();
    // The node vectors hold the mesh's directions only (2D: no z component).
    ASSERT_EQ(gm.velocityL.ncomp(), dim);
    core::forEach(gm.velocityL.box(), [&](int i, int j, int k) {
      for (int d = 0; d < dim; ++d) gm.velocityL(i, j, k, d) = kU[d];
    });
    core::Field P("P", core::Centering::Cell, cs.mass.box(), 3, 0, 0.0);
    ops.cellLagrangianMomentum(0, P);
    core::forEach(P.box(), [&](int i, int j, int k) {
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(P(i, j, k, d), d < dim ? cs.mass(i, j, k) * kU[d] : 0.0, 1e-12);
    });
  }
}

// The exchange momentum divided by the cell mass: m_c du everywhere gives every particle du.
TEST(NodeCellOperators, MomentumIncrementIsDividedByTheCellMass) {
  MpmSolver solver(scene(2), self());
  start(solver);
  NodeCellOperators& ops = solver.cells();
  const SolidCellState& cs = ops.cellState(0);
  solver.computeInternalForces();
  solver.updateGrid();
  core::Field dp("dp", core::Centering::Cell, cs.mass.box(), 3, 0, 0.0);
  core::forEach(dp.box(), [&](int i, int j, int k) { dp(i, j, k, 1) = 0.05 * cs.mass(i, j, k); });
  const double v0 = solver.centerOfMassVelocity()[1];
  ops.applyCellMomentumIncrement(0, dp);
  solver.gridToParticles();
  solver.endStep();
  EXPECT_NEAR(solver.centerOfMassVelocity()[1] - v0, 0.05, 1e-9);  // interior block
}

TEST(NodeCellOperators, ReferencePressureIsTheSolidsThreshold) {
  auto s = scene(2);
  EXPECT_EQ(MpmSolver(s, self()).cells().referencePressure(), kReferencePressure);
  s.materials[0].eos.params = {{"threshold_pressure", 2e5}};
  EXPECT_EQ(MpmSolver(s, self()).cells().referencePressure(), 2e5);
}

// Per-step data of one step refuses to serve in another: each operator names itself.
TEST(NodeCellOperators, StampRefusesStaleData) {
  MpmSolver solver(scene(2), self());
  NodeCellOperators& ops = solver.cells();
  const core::Box owned = solver.decomposition().cellBox(0);
  core::Field cell3("c", core::Centering::Cell, owned, 3, 0, 0.0);
  auto expectRefused = [&](const std::string& op, auto&& call) {
    try {
      call();
      ADD_FAILURE() << op << " accepted stale data";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find(op), std::string::npos) << e.what();
    }
  };
  // Never computed.
  expectRefused("cellLagrangianMomentum", [&] { ops.cellLagrangianMomentum(0, cell3); });
  start(solver);
  ops.cellState(0);
  EXPECT_NO_THROW(ops.addCellForce(0, cell3));
  solver.computeInternalForces();
  solver.updateGrid();
  EXPECT_NO_THROW(ops.cellLagrangianMomentum(0, cell3));
  solver.gridToParticles();
  solver.endStep();
  // The next step, before cellState(0): the state of the last step is refused.
  solver.beginStep(solver.stableTimeStep());
  solver.particlesToGrid();
  expectRefused("cellLagrangianMomentum", [&] { ops.cellLagrangianMomentum(0, cell3); });
  expectRefused("applyCellVelocityIncrement", [&] { ops.applyCellVelocityIncrement(0, cell3); });
  expectRefused("applyCellMomentumIncrement", [&] { ops.applyCellMomentumIncrement(0, cell3); });
  expectRefused("addCellForce", [&] { ops.addCellForce(0, cell3); });
  try {
    ops.addCellForce(0, cell3);
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("call cellState(0) first in this step"), std::string::npos) << e.what();
  }
  ops.cellState(0);
  EXPECT_NO_THROW(ops.addCellForce(0, cell3));
}

// Cell values reach the particles through the nodes and the particle's own shape function: a
// linear cell field is reproduced exactly at particles whose stencil holds interior mesh nodes
// only (node averages of a linear field are exact there), for every shape function, and an
// offset (p_ref) is subtracted.
TEST(NodeCellOperators, CellToParticlesReproducesLinearFields) {
  for (const char* shape : {"linear", "gimp", "bspline2", "bspline3"})
    for (int dim : {2, 3}) {
      auto s = scene(dim);
      s.mpm.shape_function = shape;
      MpmSolver solver(s, self());
      start(solver);
      const core::Mesh& mesh = solver.scene().mesh;
      const core::Box owned = solver.decomposition().cellBox(0);
      core::Field pc("p", core::Centering::Cell, owned, 1, 0, 0.0);
      auto linear = [&](double x, double y, double z) { return 3.0e5 + 2.0e5 * x - 7.0e4 * y + (dim == 3 ? 4.0e4 * z : 0.0); };
      core::forEach(owned, [&](int i, int j, int k) {
        pc(i, j, k) = linear(mesh.cellCenter(0, i), mesh.cellCenter(1, j), dim == 3 ? mesh.cellCenter(2, k) : 0.0);
      });
      std::vector<double> pp;
      solver.cells().cellToParticles(pc, 1.0e5, pp);
      const auto& p = solver.particles();
      ASSERT_EQ(pp.size(), p.size());
      for (std::size_t i = 0; i < p.size(); ++i)  // the block lies 2 cells inside the walls
        EXPECT_NEAR(pp[i], linear(p.x[0][i], p.x[1][i], dim == 3 ? p.x[2][i] : 0.0) - 1.0e5, 1e-8 * 3e5)
            << shape << " dim " << dim << " particle " << i;
    }
}

// A pressure equal to p_ref everywhere adds no force; a uniform p - p_ref adds forces that sum to
// zero (a pure surface traction: only nodes of the block's surface cells get any).
TEST(NodeCellOperators, UniformPressureStressIsASurfaceTraction) {
  for (const char* shape : {"linear", "bspline2"}) {
    auto s = scene(2);
    s.mpm.shape_function = shape;
    MpmSolver solver(s, self());
    start(solver);
    solver.computeInternalForces();
    const core::Box owned = solver.decomposition().cellBox(0);
    const double pRef = solver.cells().referencePressure();
    core::Field pc("p", core::Centering::Cell, owned, 1, 0, pRef);
    const Grid& g = solver.grid();
    core::Field before = g.externalForce;
    solver.cells().addCellPressureStress(pc);
    core::forEach(g.externalForce.box(), [&](int i, int j, int k) {
      for (int d = 0; d < 2; ++d) EXPECT_EQ(g.externalForce(i, j, k, d), before(i, j, k, d)) << shape;
    });
    core::forEach(owned, [&](int i, int j, int k) { pc(i, j, k) = pRef + 1.0e6; });
    solver.cells().addCellPressureStress(pc);
    double total[2] = {0, 0}, largest = 0;
    core::forEach(solver.scene().mesh.nodeBox(), [&](int i, int j, int k) {
      for (int d = 0; d < 2; ++d) {
        const double df = g.externalForce(i, j, k, d) - before(i, j, k, d);
        total[d] += df;
        largest = std::max(largest, std::abs(df));
      }
    });
    EXPECT_GT(largest, 0.0) << shape;
    for (double t : total) EXPECT_NEAR(t, 0.0, 1e-12 * largest) << shape;
  }
}

// The particles' thermal energy sum m_p cv T_p [J].
double heat(const mpm::ParticleSet& p, double cv) {
  double h = 0;
  for (std::size_t i = 0; i < p.size(); ++i) h += p.mass[i] * cv * p.temperature[i];
  return h;
}

// addCellEnergy with several fields (the coupled step hands the exchange heat and the kinetic
// deficit at once) distributes their per-cell sum: the same temperatures, bit for bit, as one call
// with the summed field (a cell's heating and cooling are not told apart field by field).
TEST(NodeCellOperators, CellEnergyOfSeveralFieldsIsTheirSum) {
  for (const char* shape : {"linear", "bspline2"})
    for (int dim : {2, 3}) {
      auto s = scene(dim);
      s.mpm.shape_function = shape;
      MpmSolver summed(s, self()), atOnce(s, self());
      start(summed);
      start(atOnce);
      const core::Box owned = summed.decomposition().cellBox(0);
      core::Field heat("heat", core::Centering::Cell, owned, 1, 0, 0.0), deficit = heat, total = heat;
      core::forEach(owned, [&](int i, int j, int k) {
        heat(i, j, k) = 10.0 + 3.0 * i - 2.0 * j + k;  // every cell, the empty ones too
        deficit(i, j, k) = 0.1 * std::sin(1.0 + i + 2.0 * j + 3.0 * k) - (i == 3 ? 40.0 : 0.0);  // some cells cool
        total(i, j, k) = 0.0 + heat(i, j, k) + deficit(i, j, k);
      });
      summed.cells().addCellEnergy(0, total);
      atOnce.cells().addCellEnergy(0, {&heat, &deficit});
      const auto &a = summed.particles(), &b = atOnce.particles();
      ASSERT_EQ(a.size(), b.size());
      std::size_t warmed = 0, cooled = 0;
      for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a.temperature[i], b.temperature[i]) << shape << " dim " << dim << " particle " << i;
        warmed += a.temperature[i] > 350.0;
        cooled += a.temperature[i] < 350.0;
      }
      EXPECT_GT(warmed, 0u) << shape << " dim " << dim;
      EXPECT_GT(cooled, 0u) << shape << " dim " << dim;
      EXPECT_EQ(warmed + cooled, a.size()) << shape << " dim " << dim;
    }
}

// A cell's negative energy (cooling) goes to its particles in proportion to their thermal energy
// m_p cv T_p: each loses the same fraction as its nodes' (a weighted mean), so a particle much
// colder than its neighbours is not driven below 0 K by the cooling they share, and the energy
// given is the energy taken, to round-off. Here the cells take a fifth of the block's thermal
// energy: with the mass weights every particle lost about 70 K, and the one at 1 K went to -69 K.
TEST(NodeCellOperators, CellCoolingTakesTheSameFractionOfEveryParticlesThermalEnergy) {
  for (const char* shape : {"linear", "bspline2"})
    for (int dim : {2, 3}) {
      auto s = scene(dim);
      s.mpm.shape_function = shape;
      MpmSolver solver(s, self());
      start(solver);
      auto& p = solver.particles();
      const double cv = solver.scene().materials[0].specific_heat;
      const std::size_t cold = p.size() / 2;
      p.temperature[cold] = 1.0;
      const double thermal = heat(p, cv);
      // The block's cells (centres inside it) share -0.2 of its thermal energy alike.
      const core::Box owned = solver.decomposition().cellBox(0);
      const core::Mesh& mesh = solver.scene().mesh;
      core::Field E("cooling", core::Centering::Cell, owned, 1, 0, 0.0);
      int inside = 0;
      auto inBlock = [&](int i, int j, int k) {
        const double x = mesh.cellCenter(0, i), y = mesh.cellCenter(1, j), z = dim == 3 ? mesh.cellCenter(2, k) : 0.0;
        return x > 0.5 && x < 1.25 && y > 0.5 && y < 1.0 && (dim == 2 || (z > 0.5 && z < 1.0));
      };
      core::forEach(owned, [&](int i, int j, int k) { inside += inBlock(i, j, k); });
      ASSERT_GT(inside, 0);
      core::forEach(owned, [&](int i, int j, int k) {
        if (inBlock(i, j, k)) E(i, j, k) = -0.2 * thermal / inside;
      });
      std::vector<double> before(p.temperature.begin(), p.temperature.end());
      solver.cells().addCellEnergy(0, E);
      double given = 0, mostLost = 0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        given += p.mass[i] * cv * (p.temperature[i] - before[i]);
        EXPECT_GT(p.temperature[i], 0.0) << shape << " dim " << dim << " particle " << i;
        if (i != cold) mostLost = std::max(mostLost, 1.0 - p.temperature[i] / before[i]);
      }
      EXPECT_NEAR(given, -0.2 * thermal, 1e-12 * thermal) << shape << " dim " << dim;
      const double coldLost = 1.0 - p.temperature[cold] / before[cold];
      EXPECT_GT(coldLost, 0.0) << shape << " dim " << dim;
      EXPECT_LE(coldLost, mostLost * (1 + 1e-12)) << shape << " dim " << dim;
    }
}

// solidFaceTransport: the face fluxes of the node-to-cell average. Moving every particle by
// kU eps changes each cell's mass by eps times the face flux into it less the flux out (checked
// by the difference of two particle-to-grid passes, for each shape and dimension), and the face
// density and flux integrate, over the faces normal to d times dx_d, to the mass and the momentum.
TEST(NodeCellOperators, FaceTransportIsTheCellMassChange) {
  for (const char* shape : {"linear", "gimp", "bspline2"})
    for (int dim : {2, 3}) {
      core::Scene sc = scene(dim);
      sc.mpm.shape_function = shape;
      MpmSolver solver(sc, self());
      start(solver);
      const core::Mesh& mesh = solver.scene().mesh;
      const core::Box cells = solver.cells().cellState(0).mass.box();
      core::Field D("density", core::Centering::Cell, cells, 3, 0), F("flux", core::Centering::Cell, cells, 3, 0);
      solver.cells().solidFaceTransport(0, D, F);
      const core::Field m0 = solver.cells().cellState(0).mass;
      auto& p = solver.particles();
      double mass = 0;
      for (std::size_t i = 0; i < p.size(); ++i) mass += p.mass[i];
      const double V = mesh.cellVolume();
      for (int d = 0; d < dim; ++d) {
        EXPECT_NEAR(sum(D, d) * V, mass, 1e-12 * mass) << shape << " " << dim << "D, d = " << d;
        EXPECT_NEAR(sum(F, d) * V, mass * kU[d], 1e-12 * mass) << shape << " " << dim << "D, d = " << d;
      }
      const double eps = 1e-6;
      for (std::size_t i = 0; i < p.size(); ++i)
        for (int d = 0; d < dim; ++d) p.x[d][i] += eps * kU[d];
      solver.beginStep(solver.stableTimeStep());
      solver.particlesToGrid();
      const core::Field& m1 = solver.cells().cellState(0).mass;
      double worst = 0;
      core::forEach(cells, [&](int i, int j, int k) {
        double inflow = 0;
        for (int d = 0; d < dim; ++d) {
          int h[3] = {i, j, k};
          h[d] += 1;
          const double A = V / mesh.dx(d);
          const double out = cells.contains(h[0], h[1], h[2]) ? F(h[0], h[1], h[2], d) : 0.0;
          inflow += A * (F(i, j, k, d) - out);
        }
        worst = std::max(worst, std::abs((m1(i, j, k) - m0(i, j, k)) / eps - inflow));
      });
      EXPECT_LT(worst, 1e-5 * mass) << shape << " " << dim << "D";
    }
}

// The coupling work (cell_coupling_work.cpp) is booked to the cell the force came from: a force in
// one cell of the block does work in that cell only (booking the nodes' work by the node-to-cell
// average put it into the 8 / 26 cells around as well), and summed over the cells it is the work
// the grid update did, sum_i dt f_i . (v_n + v_L) / 2 (Grid::externalWork). The same for the
// mean-stress force of a pressure jump, whose work sums to the nodes' too.
TEST(NodeCellOperators, CouplingWorkIsBookedToTheCellTheForceCameFrom) {
  for (int dim : {2, 3}) {
    MpmSolver solver(scene(dim), self());
    start(solver);
    NodeCellOperators& ops = solver.cells();
    const SolidCellState& cs = ops.cellState(0);
    solver.computeInternalForces();
    core::Field f("force", core::Centering::Cell, cs.mass.box(), 3, 0, 0.0);
    const int ci = 3, cj = 2, ck = dim == 3 ? 2 : 0;  // inside the block (cells 2..4 x 2..3 x 2..3)
    f(ci, cj, ck, 0) = 40.0;
    f(ci, cj, ck, 1) = -25.0;
    ops.addCellForce(0, f);
    solver.updateGrid();
    core::Field W("work", core::Centering::Cell, cs.mass.box(), 1, 0, 0.0);
    ops.cellCouplingWork(0, W, solver.stepSize());
    const double nodes = sum(solver.grid().externalWork);
    EXPECT_GT(std::abs(nodes), 0.0) << dim;
    EXPECT_NEAR(sum(W), nodes, 1e-12 * std::abs(nodes)) << dim;
    core::forEach(W.box(), [&](int i, int j, int k) {
      if (i != ci || j != cj || k != ck) {
        EXPECT_EQ(W(i, j, k), 0.0) << dim << " cell " << i << "," << j << "," << k;
      }
    });
  }
  // The mean-stress force of a pressure that rises across the block (its work is the particles').
  MpmSolver solver(scene(2), self());
  start(solver);
  NodeCellOperators& ops = solver.cells();
  const SolidCellState& cs = ops.cellState(0);
  solver.computeInternalForces();
  core::Field p("pressure", core::Centering::Cell, cs.mass.box(), 1, 0, 0.0);
  core::forEach(p.box(), [&](int i, int j, int k) { p(i, j, k) = 1e5 + 2e4 * i + 5e3 * j; });
  ops.addCellPressureStress(p);
  solver.updateGrid();
  core::Field W("work", core::Centering::Cell, cs.mass.box(), 1, 0, 0.0);
  ops.cellCouplingWork(0, W, solver.stepSize());
  const double nodes = sum(solver.grid().externalWork);
  EXPECT_GT(std::abs(nodes), 0.0);
  EXPECT_NEAR(sum(W), nodes, 1e-12 * std::abs(nodes));
}

// The kinetic deficit of a momentum increment (applyCellMomentumIncrement) is booked to the cell
// the increment came from: zero in every other cell (the nodes' gain node-to-cell averaged put a
// negative deficit into the cells around it), and in that cell what the cell's view charged,
// dp . (u_L + dv / 2), less the kinetic energy all the nodes gained.
TEST(NodeCellOperators, KineticDeficitIsBookedToTheCellTheIncrementCameFrom) {
  for (int dim : {2, 3}) {
    MpmSolver solver(scene(dim), self());
    start(solver);
    solver.computeInternalForces();
    solver.updateGrid();
    const CellIncrement c = applyCellIncrement(solver);
    double nodes = 0;
    const Grid& g = solver.grid();
    for (std::int64_t k = 0; k < g.numNodes(); ++k)
      for (int d = 0; d < dim; ++d) {
        const double a = c.vOld.data(d)[k], b = g.velocityL.data(d)[k];
        nodes += 0.5 * g.mass.data()[k] * (b * b - a * a);
      }
    EXPECT_NEAR(solver.cells().kineticDeficit(0)(c.i, c.j, c.k), c.gain - nodes, 1e-12 * std::abs(c.gain)) << dim;
  }
}

// The grid's stress-work count (mpm.stress_work grid, a coupled run's `auto`) takes the node
// velocity the step ends with, after the exchange's increments (the particles deform with them):
// the particles' work changes by -sum_i dt f_i . (v_i + v_L,i) / 2 with the final v_L, and the
// increments' kinetic deficit gives the forces' share of their kinetic energy, sum_i dt f_i . dv_i
// / 2, to that work instead of to the heat (with either count); MPM's ledger is left with the body
// forces' work (none here), or with `material` the models' count less the forces' work. With the
// count taken before the increments the flap's stored work went below zero
// (docs/mpm.md "Stress work").
TEST(NodeCellOperators, GridStressWorkTakesTheExchangeIncrementsShareOfTheForcesWork) {
  for (const char* count : {"grid", "material"}) {
    for (int dim : {2, 3}) {
      const bool grid = std::string(count) == "grid";
      core::Scene sc = scene(dim);
      sc.mpm.stress_work = count;
      MpmSolver solver(sc, self());
      start(solver);
      auto& p = solver.particles();
      for (std::size_t i = 0; i < p.size(); ++i) {  // a stress that varies across the block: node forces
        p.stress[kXX][i] = 2e3 * p.x[0][i] + 500.0 * p.x[1][i];
        p.stress[kYY][i] = -1e3 * p.x[1][i];
        p.stress[kXY][i] = 300.0 * p.x[0][i] * p.x[1][i];
      }
      double work0 = 0;
      for (std::size_t i = 0; i < p.size(); ++i) work0 += p.work[i];
      solver.computeInternalForces();
      solver.updateGrid();
      const CellIncrement c = applyCellIncrement(solver);
      const Grid& g = solver.grid();
      double nodes = 0, share = 0, force = 0, fend = 0;
      for (std::int64_t k = 0; k < g.numNodes(); ++k)
        for (int d = 0; d < dim; ++d) {
          const double a = c.vOld.data(d)[k], b = g.velocityL.data(d)[k], f = g.force.data(d)[k];
          nodes += 0.5 * g.mass.data()[k] * (b * b - a * a);
          share += 0.5 * solver.stepSize() * f * (b - a);
          force += std::abs(f);
          fend += solver.stepSize() * f * 0.5 * (g.velocity.data(d)[k] + b);
        }
      ASSERT_GT(force, 0.0) << dim;
      ASSERT_GT(std::abs(share), 1e-6 * std::abs(c.gain)) << dim;  // the increment moves nodes the forces act on
      // The heat does not depend on which count is reported.
      EXPECT_NEAR(solver.cells().kineticDeficit(0)(c.i, c.j, c.k), c.gain - nodes + share, 1e-10 * std::abs(c.gain))
          << count << " " << dim;
      solver.gridToParticles();
      double work1 = 0;
      for (std::size_t i = 0; i < p.size(); ++i) work1 += p.work[i];
      // grid: the work is the forces' at the end velocity, and the ledger is left with nothing (no
      // body forces); material: the ledger is the models' count less that.
      if (grid) {
        EXPECT_NEAR(work1 - work0, -fend, 1e-10 * std::abs(fend)) << dim;
      }
      EXPECT_NEAR(solver.energies().integration, (work1 - work0) + fend, 1e-10 * std::abs(fend)) << count << " " << dim;
    }
  }
}

// Open faces (free, outflow: ICE continues its fields beyond them with zero gradient): a block that
// spans the mesh between two open y faces continues beyond them as far as the coupled step is
// concerned (node_cell_operators.h openFaceNodes, open_face_images.h). (a) Moving every particle
// along the face normal changes no cell's mass (the face nodes carry the zero-gradient images; the
// face share of 1 read a gap of eps / dx in one boundary row and an overfill in the other); (b)
// a uniform p - p_ref puts no force normal to the open faces on any node (the mean-stress
// correction has no boundary term there: the weak form left -q times the face area on the face
// nodes, the force that grew a plate at rest between free faces from round-off), while the
// block's sides, real surfaces, keep their traction; also once the block has moved along the
// normal (the nodes next to the gap its particles left: the gradient form reaches two node
// layers into the mesh).
TEST(NodeCellOperators, SolidContinuesBeyondOpenFaces) {
  for (const core::BoundaryType open : {core::BoundaryType::Free, core::BoundaryType::Outflow})
    for (const char* shape : {"linear", "gimp", "bspline2"})
      for (int dim : {2, 3}) {
        core::Scene s = scene(dim);
        s.mpm.shape_function = shape;
        s.boundary[2].type = s.boundary[3].type = open;
        s.geometry.front().shape.lo[1] = 0.0;
        s.geometry.front().shape.hi[1] = 2.0;  // the mesh's height (8 cells of 0.25)
        const std::string what = std::string(shape) + " " + std::to_string(dim) + "D" +
                                 (open == core::BoundaryType::Free ? " free" : " outflow");
        MpmSolver solver(s, self());
        start(solver);
        const core::Field m0 = solver.cells().cellState(0).mass;
        double largestCell = 0;
        core::forEach(m0.box(), [&](int i, int j, int k) { largestCell = std::max(largestCell, m0(i, j, k)); });
        // (b) The mean-stress force of a uniform p - p_ref.
        auto normalForce = [&](const char* when) {
          solver.computeInternalForces();
          const core::Box owned = solver.decomposition().cellBox(0);
          const double pRef = solver.cells().referencePressure();
          core::Field pc("p", core::Centering::Cell, owned, 1, 0, pRef + 1.0e6);
          const Grid& g = solver.grid();
          const core::Field before = g.externalForce;
          solver.cells().addCellPressureStress(pc);
          double largestSide = 0, largestNormal = 0;
          core::forEach(g.externalForce.box(), [&](int i, int j, int k) {
            largestSide = std::max(largestSide, std::abs(g.externalForce(i, j, k, 0) - before(i, j, k, 0)));
            largestNormal = std::max(largestNormal, std::abs(g.externalForce(i, j, k, 1) - before(i, j, k, 1)));
          });
          EXPECT_GT(largestSide, 0.0) << what << " " << when;
          EXPECT_LT(largestNormal, 1e-12 * largestSide) << what << " " << when;
        };
        normalForce("at the start");
        // (a) Every cell column the block fills holds the same mass in every row, and a shift of
        // 0.1 dx along y moves no mass between rows.
        core::forEach(m0.box(), [&](int i, int j, int k) {
          EXPECT_NEAR(m0(i, j, k), m0(i, 0, k), 1e-12 * largestCell) << what << " cell " << i << "," << j << "," << k;
        });
        auto& p = solver.particles();
        for (std::size_t i = 0; i < p.size(); ++i) p.x[1][i] += 0.025;
        solver.beginStep(solver.stableTimeStep());
        solver.particlesToGrid();
        const core::Field& m1 = solver.cells().cellState(0).mass;
        core::forEach(m0.box(), [&](int i, int j, int k) {
          EXPECT_NEAR(m1(i, j, k), m0(i, j, k), 1e-12 * largestCell) << what << " cell " << i << "," << j << "," << k;
        });
        normalForce("moved by 0.1 dx");
      }
}

// A cell's cooling takes its solid's heat down to kMinCellTemperatureShare of the material's mean
// temperature at most; the rest goes to every particle of the material in proportion to its thermal
// energy, and is counted: the particles stay above 0 K and the energy given is the energy taken.
// Repeated step after step (the leading edge of a solid where the correction cools every step),
// the cell's particles settle near that floor instead of halving towards 0 K.
TEST(NodeCellOperators, CellCoolingBelowTheFloorGoesToTheWholeMaterial) {
  for (const char* shape : {"linear", "bspline2"})
    for (int dim : {2, 3}) {
      auto s = scene(dim);
      s.mpm.shape_function = shape;
      MpmSolver solver(s, self());
      start(solver);
      const double cv = solver.scene().materials[0].specific_heat;
      auto& p = solver.particles();
      const double thermal = heat(p, cv);
      const core::Box owned = solver.decomposition().cellBox(0);
      core::Field E("cooling", core::Centering::Cell, owned, 1, 0, 0.0);
      E(3, 2, dim == 3 ? 2 : 0) = -0.3 * thermal;  // one cell inside the block: far beyond its own heat
      std::vector<double> before(p.temperature.begin(), p.temperature.end());
      EXPECT_EQ(solver.cells().spreadCooling().cells, 0);
      solver.cells().addCellEnergy(0, E);
      double given = 0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        given += p.mass[i] * cv * (p.temperature[i] - before[i]);
        EXPECT_GT(p.temperature[i], 0.0) << shape << " dim " << dim << " particle " << i;
        EXPECT_LT(p.temperature[i], before[i]) << shape << " dim " << dim << " particle " << i;  // every one shares it
      }
      EXPECT_NEAR(given, -0.3 * thermal, 1e-12 * thermal) << shape << " dim " << dim;
      const auto& spread = solver.cells().spreadCooling();
      EXPECT_EQ(spread.cells, 1) << shape << " dim " << dim;
      EXPECT_EQ(spread.steps, 1) << shape << " dim " << dim;
      EXPECT_LT(spread.energy, -0.2 * thermal) << shape << " dim " << dim;  // most of it: the cell holds little
      EXPECT_GT(spread.energy, -0.3 * thermal) << shape << " dim " << dim;
      // 200 more calls, each taking 0.1 % of the block's heat from that cell (as much again as the
      // first call's, in small steps).
      E(3, 2, dim == 3 ? 2 : 0) = -0.001 * thermal;
      for (int n = 0; n < 200; ++n) solver.cells().addCellEnergy(0, E);
      double mass = 0, heatLeft = 0, coldest = 1e30;
      for (std::size_t i = 0; i < p.size(); ++i) {
        mass += p.mass[i];
        heatLeft += p.mass[i] * cv * p.temperature[i];
        coldest = std::min(coldest, p.temperature[i]);
      }
      EXPECT_NEAR(heatLeft, 0.5 * thermal, 1e-10 * thermal) << shape << " dim " << dim;
      const double mean = heatLeft / (mass * cv);
      std::printf("%s dim %d: mean %.2f K, coldest %.2f K\n", shape, dim, mean, coldest);
      EXPECT_GT(coldest, 0.3 * mean) << shape << " dim " << dim;
    }
}
