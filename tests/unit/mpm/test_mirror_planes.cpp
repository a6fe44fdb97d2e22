// Symmetry planes as mirrors: a particle block touching symmetry planes gives the same node
// masses and velocities, and after several steps the same particle positions, velocities and
// stresses, as the full mirrored block computed with no plane, for every shape function (the
// wide stencils fold their ghost-node contributions onto the mirror nodes and read the mirrored
// ghost values back). Plus conservation of mass and tangential momentum at the planes.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include "mpm_problems.h"
#include "core/parallel/comm.h"
#include "serial_mpi.h"

using namespace mpmice;
using namespace mpmice::mpm;
namespace pr = mpmice::mpm::problems;

namespace {

core::Comm self() { return core::Comm(MPI_COMM_SELF); }

constexpr int kCells = 8;          // half mesh cells per direction
constexpr double kDx = 0.25;
constexpr double kL = kCells * kDx;  // half mesh length
constexpr double kBlock = 0.75;      // block extent from a plane

struct Case {
  int dim;
  const char* shape;
  int mirrorMask;    // bit d: a mirror plane normal to direction d
  bool high = false;  // the x plane at the high face (x = kL) instead of x = 0
};

/// Plane position (mirrored directions) or block centre (others): the field coordinates' origin.
double centre(const Case& c, int d) {
  if (c.mirrorMask >> d & 1) return d == 0 && c.high ? kL : 0.0;
  return 0.875;
}

/// The half (full = false) or the full mirrored (full = true) scene.
core::Scene scene(const Case& c, bool full) {
  core::Scene s;
  core::RealVect origin{0, 0, 0};
  core::IntVect cells{1, 1, 1};
  core::ShapeSpec box;
  box.type = "box";
  for (int d = 0; d < c.dim; ++d) {
    cells[d] = kCells;
    const bool m = c.mirrorMask >> d & 1;
    if (m && full) {
      cells[d] = 2 * kCells;
      origin[d] = d == 0 && c.high ? 0.0 : -kL;
    }
    const double p = centre(c, d);
    if (!m) {
      box.lo[d] = 0.5;
      box.hi[d] = 1.25;
    } else if (d == 0 && c.high) {
      box.lo[d] = p - kBlock;
      box.hi[d] = full ? p + kBlock : p;
    } else {
      box.lo[d] = full ? p - kBlock : p;
      box.hi[d] = p + kBlock;
    }
  }
  s.mesh = core::Mesh(c.dim, origin, {kDx, c.dim > 1 ? kDx : 1.0, c.dim > 2 ? kDx : 1.0}, cells);
  for (auto& f : s.boundary) f.type = core::BoundaryType::Free;
  if (!full)
    for (int d = 0; d < c.dim; ++d)
      if (c.mirrorMask >> d & 1)
        s.boundary[2 * d + (d == 0 && c.high ? 1 : 0)].type = core::BoundaryType::Symmetry;
  s.time.cfl = 0.4;
  s.materials = {pr::solid("block", 1000, pr::elastic("linear_elastic", 1e6, 0.25))};
  s.geometry = {pr::region("block", box, "block", {2, 2, 2})};
  s.mpm.shape_function = c.shape;
  return s;
}

/// Mirror-symmetric initial velocity (v_d odd in u_d, even in the others) and stress.
void initialise(const Case& c, MpmSolver& solver) {
  auto& p = solver.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    double u[3] = {0, 0, 0}, u2 = 0;
    for (int d = 0; d < c.dim; ++d) {
      u[d] = p.x[d][i] - centre(c, d);
      u2 += u[d] * u[d];
    }
    for (int d = 0; d < c.dim; ++d) p.v[d][i] = 0.1 * u[d] * (1 + u2 - u[d] * u[d]);
    for (int d = 0; d < 3; ++d) p.stress[d][i] = 1e3 * (1 + u2 + u[d] * u[d]);
    p.stress[kXY][i] = 1e2 * u[0] * u[1];
    if (c.dim == 3) {  // in 2D the yz and xz stresses are exact zeros, not stored
      p.stress[kYZ][i] = 1e2 * u[1] * u[2];
      p.stress[kXZ][i] = 1e2 * u[0] * u[2];
    }
  }
}

using Key = std::tuple<long, long, long>;
Key keyOf(const ParticleSet& p, std::size_t i) {
  return {std::lround(p.x[0][i] * 1e6), std::lround(p.x[1][i] * 1e6), std::lround(p.x[2][i] * 1e6)};
}

void compareWithFullBlock(const Case& c) {
  SCOPED_TRACE(std::string(c.shape) + " dim " + std::to_string(c.dim) + " mask " +
               std::to_string(c.mirrorMask) + (c.high ? " high" : ""));
  MpmSolver half(scene(c, false), self()), full(scene(c, true), self());
  initialise(c, half);
  initialise(c, full);
  const auto& mesh = half.scene().mesh;
  // Node offset of the half mesh in the full one.
  int off[3] = {0, 0, 0};
  for (int d = 0; d < c.dim; ++d)
    if ((c.mirrorMask >> d & 1) && !(d == 0 && c.high)) off[d] = kCells;

  // 1. Node masses and velocities after particle-to-grid.
  half.projectToGrid();
  full.projectToGrid();
  double mScale = 0, vScale = 0;
  core::forEach(mesh.nodeBox(), [&](int i, int j, int k) {
    mScale = std::max(mScale, half.grid().mass(i, j, k));
    for (int d = 0; d < c.dim; ++d) vScale = std::max(vScale, std::fabs(half.grid().velocity(i, j, k, d)));
  });
  ASSERT_GT(mScale, 0.0);
  core::forEach(mesh.nodeBox(), [&](int i, int j, int k) {
    const int idx[3] = {i, j, k};
    int onPlanes = 0;
    for (int d = 0; d < c.dim; ++d)
      if ((c.mirrorMask >> d & 1) && idx[d] == (d == 0 && c.high ? kCells : 0)) ++onPlanes;
    const int fi = i + off[0], fj = j + off[1], fk = k + off[2];
    // A node on a plane gets the mirror particles' share too in the full block.
    EXPECT_NEAR(full.grid().mass(fi, fj, fk), (1 << onPlanes) * half.grid().mass(i, j, k), 1e-12 * mScale)
        << i << " " << j << " " << k;
    for (int d = 0; d < c.dim; ++d)
      EXPECT_NEAR(full.grid().velocity(fi, fj, fk, d), half.grid().velocity(i, j, k, d), 1e-12 * vScale)
          << i << " " << j << " " << k << " component " << d;
  });

  // 2. Conservation at the planes: node mass and tangential momentum on the half mesh's nodes
  //    (ghosts excluded) equal the particles' totals.
  {
    const auto& p = half.particles();
    double pm = 0, pmom[3] = {0, 0, 0};
    for (std::size_t i = 0; i < p.size(); ++i) {
      pm += p.mass[i];
      for (int d = 0; d < c.dim; ++d) pmom[d] += p.mass[i] * p.v[d][i];
    }
    double gm = 0, gmom[3] = {0, 0, 0};
    core::forEach(mesh.nodeBox(), [&](int i, int j, int k) {
      const double m = half.grid().mass(i, j, k);
      gm += m;
      for (int d = 0; d < c.dim; ++d) gmom[d] += m * half.grid().velocity(i, j, k, d);
    });
    EXPECT_NEAR(gm, pm, 1e-12 * pm);
    for (int d = 0; d < c.dim; ++d) {
      if (!(c.mirrorMask >> d & 1)) {
        EXPECT_NEAR(gmom[d], pmom[d], 1e-12 * pm * vScale) << "component " << d;
      }
    }
  }

  // 3. Particles after a few full steps.
  std::map<Key, std::int64_t> halfId, fullId;  // initial position -> id
  for (std::size_t i = 0; i < half.particles().size(); ++i)
    halfId[keyOf(half.particles(), i)] = half.particles().id[i];
  for (std::size_t i = 0; i < full.particles().size(); ++i)
    fullId[keyOf(full.particles(), i)] = full.particles().id[i];
  std::map<std::int64_t, std::int64_t> halfToFull;
  for (const auto& [k, id] : halfId) {
    ASSERT_TRUE(fullId.count(k));
    halfToFull[id] = fullId.at(k);
  }
  for (int s = 0; s < 10; ++s) {
    const double dt = half.advance();
    EXPECT_NEAR(full.advance(), dt, 1e-14 * dt);
  }
  std::map<std::int64_t, std::size_t> fullIndex;
  const auto& pf = full.particles();
  for (std::size_t i = 0; i < pf.size(); ++i) fullIndex[pf.id[i]] = i;
  const auto& ph = half.particles();
  double sScale = 0, dMax = 0;
  for (std::size_t i = 0; i < ph.size(); ++i)
    for (int k = 0; k < 6; ++k)
      if (ph.stored(ph.stress[k])) sScale = std::max(sScale, std::fabs(ph.stress[k][i]));
  for (std::size_t i = 0; i < ph.size(); ++i) {
    const std::size_t j = fullIndex.at(halfToFull.at(ph.id[i]));
    for (int d = 0; d < c.dim; ++d) {
      EXPECT_NEAR(ph.x[d][i], pf.x[d][j], 1e-12);
      EXPECT_NEAR(ph.v[d][i], pf.v[d][j], 1e-12 * vScale);
    }
    for (int k = 0; k < 6; ++k) {
      if (!ph.stored(ph.stress[k])) continue;  // 2D: yz, xz are exact zeros, not stored
      EXPECT_NEAR(ph.stress[k][i], pf.stress[k][j], 1e-10 * sScale) << "stress " << k;
      dMax = std::max(dMax, std::fabs(ph.stress[k][i] - pf.stress[k][j]));
    }
  }
  // The stress did change over the steps (the comparison is not trivial).
  double changed = 0;
  for (std::size_t i = 0; i < ph.size(); ++i) changed = std::max(changed, std::fabs(ph.work[i]));
  EXPECT_GT(changed, 0.0);
  std::printf("[mirror %s dim %d mask %d%s] %zu particles, max stress difference %.2e of %.2e\n", c.shape,
              c.dim, c.mirrorMask, c.high ? " high" : "", ph.size(), dMax, sScale);
}
}  // namespace

TEST(BoundaryMirror, EveryShapeMatchesFullBlock2D) {
  for (const char* shape : {"linear", "gimp", "bspline2", "bspline3"}) compareWithFullBlock({2, shape, 1});
}

TEST(BoundaryMirror, CornerOfTwoPlanes2D) {
  for (const char* shape : {"gimp", "bspline2", "bspline3"}) compareWithFullBlock({2, shape, 3});
}

TEST(BoundaryMirror, HighFace2D) {
  for (const char* shape : {"bspline2", "bspline3"}) compareWithFullBlock({2, shape, 1, true});
}

TEST(BoundaryMirror, OneAndThreeDimensions) {
  compareWithFullBlock({1, "bspline3", 1});
  compareWithFullBlock({1, "bspline2", 1, true});
  compareWithFullBlock({3, "bspline2", 7});
}

TEST(BoundaryMirror, GhostNodesMirrorTheInside) {
  core::Scene s = scene({2, "bspline2", 1}, false);
  s.boundary[2].type = core::BoundaryType::SlipWall;  // y-: a mirror too
  s.boundary[3].type = core::BoundaryType::NoSlipWall;
  const core::Box nodes = core::Box({-1, -1, 0}, {kCells + 1, kCells + 1, 0});
  BoundaryConditions bc(s.boundary, s.mesh, nodes);
  core::Field v("v", core::Centering::Node, nodes, 3, 1, 0.0);
  core::forEach(nodes, [&](int i, int j, int k) {
    v(i, j, k, 0) = 1 + i + 10 * j;
    v(i, j, k, 1) = 2 + i * j;
  });
  bc.apply(v);
  EXPECT_EQ(v(0, 4, 0, 0), 0.0);                   // on the x plane: normal 0
  EXPECT_EQ(v(0, 4, 0, 1), 2.0);                   //                tangential kept
  EXPECT_EQ(v(-1, 4, 0, 0), -v(1, 4, 0, 0));       // ghost: mirror, normal negated
  EXPECT_EQ(v(-1, 4, 0, 1), v(1, 4, 0, 1));
  EXPECT_EQ(v(3, -1, 0, 1), -v(3, 1, 0, 1));       // slip wall mirrors too
  EXPECT_EQ(v(-1, -1, 0, 0), -v(1, 1, 0, 0));      // corner: mirrored twice
  EXPECT_EQ(v(-1, -1, 0, 1), -v(1, 1, 0, 1));
  EXPECT_EQ(v(3, kCells + 1, 0, 0), 0.0);          // no-slip wall: fixed beyond it
  EXPECT_EQ(v(-1, kCells + 1, 0, 1), 0.0);
  // fold: the ghost's contribution lands on the mirror node, the ghost is cleared.
  core::Field m("m", core::Centering::Node, nodes, 3, 1, 0.0);
  m(-1, 4, 0, 0) = 1.0;
  m(-1, 4, 0, 1) = 2.0;
  m(-1, -1, 0, 0) = 4.0;
  bc.fold(m, Parity::Vector);
  EXPECT_EQ(m(-1, 4, 0, 0), 0.0);
  EXPECT_EQ(m(1, 4, 0, 0), -1.0);
  EXPECT_EQ(m(1, 4, 0, 1), 2.0);
  EXPECT_EQ(m(-1, -1, 0, 0), 0.0);
  EXPECT_EQ(m(1, 1, 0, 0), -4.0);
}
