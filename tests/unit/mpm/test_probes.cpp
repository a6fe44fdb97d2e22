// ProbeRecorder (src/mpm/solver/probes.h): a probe follows the particle nearest to its point,
// found by global id wherever it migrates. A free elastic block in uniform motion moves rigidly,
// so the probe's displacement is v t and its position x0 + v t; the chosen particle and the
// figures are the same on any number of ranks (run on 1 and 4: the block crosses rank borders).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "mpm_problems.h"
#include "mpm/solver/probes.h"
#include "test_comm.h"

using namespace mpmice;
using namespace mpmice::mpm;
namespace pr = mpmice::mpm::problems;

namespace {

constexpr double kV[2] = {0.9, 0.8};

// 16 x 16 cells on the unit square, free faces; a 4 x 4-cell block with 2 x 2 particles per cell,
// moving at kV (on 4 ranks the 2 x 2 process grid splits at 0.5, which the block crosses).
core::Scene movingBlock() {
  core::Scene s;
  s.name = "probe_block";
  s.mesh = core::Mesh(2, {0, 0, 0}, {1.0 / 16, 1.0 / 16, 1}, {16, 16, 1});
  for (auto& f : s.boundary) f.type = core::BoundaryType::Free;
  s.materials = {pr::solid("block", 1000, pr::elastic("linear_elastic", 1e4, 0.3))};
  core::ShapeSpec box;
  box.type = "box";
  box.lo = {0.125, 0.125, 0};
  box.hi = {0.375, 0.375, 0};
  s.geometry = {pr::region("block", box, "block", {2, 2, 1})};
  s.geometry[0].velocity = {kV[0], kV[1], 0};
  s.time.end = 0.2;
  return s;
}

core::ProbeSpec probe(const std::string& name, double x, double y) {
  core::ProbeSpec p;
  p.name = name;
  p.point = {x, y, 0};
  return p;
}

// Brute force on one rank: the lowest id among the particles nearest to (x, y).
std::int64_t nearestId(const MpmSolver& serial, double x, double y) {
  const ParticleSet& p = serial.particles();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) best = std::min(best, std::hypot(p.x0[0][i] - x, p.x0[1][i] - y));
  std::int64_t id = std::numeric_limits<std::int64_t>::max();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (std::hypot(p.x0[0][i] - x, p.x0[1][i] - y) <= best * (1 + 1e-9) + 1e-14) id = std::min(id, p.id[i]);
  return id;
}

}  // namespace

TEST(ProbeRecorder, PicksTheNearestParticleAndTheLowestIdOnTies) {
  const core::Scene s = movingBlock();
  MpmSolver solver(s, test::comm());
  // (0.25, 0.25): the block's centre, equidistant from four particles (a tie); (0.125, 0.375):
  // a corner; (0.9, 0.9): far outside, still the nearest particle (the opposite corner).
  const std::vector<core::ProbeSpec> probes{probe("centre", 0.25, 0.25), probe("corner", 0.125, 0.375),
                                            probe("far", 0.9, 0.9)};
  ProbeRecorder rec(solver, probes, "");
  if (test::comm().root()) {
    MpmSolver serial(s, core::Comm(MPI_COMM_SELF));
    for (std::size_t k = 0; k < probes.size(); ++k)
      EXPECT_EQ(rec.particleIds()[k], nearestId(serial, probes[k].point[0], probes[k].point[1])) << probes[k].name;
  }
  rec.record(solver);
  const double h = 1.0 / 32;  // particle spacing
  EXPECT_NEAR(std::hypot(rec.samples()[0].x[0] - 0.25, rec.samples()[0].x[1] - 0.25), std::hypot(h / 2, h / 2),
              1e-12);
  EXPECT_NEAR(rec.samples()[1].x[0], 0.125 + h / 2, 1e-12);
  EXPECT_NEAR(rec.samples()[1].x[1], 0.375 - h / 2, 1e-12);
  EXPECT_NEAR(rec.samples()[2].x[0], 0.375 - h / 2, 1e-12);
  EXPECT_NEAR(rec.samples()[2].x[1], 0.375 - h / 2, 1e-12);
  for (const auto& smp : rec.samples()) EXPECT_EQ(smp.u[0], 0.0);
}

TEST(ProbeRecorder, FollowsItsParticleInUniformMotion) {
  const core::Scene s = movingBlock();
  MpmSolver solver(s, test::comm());
  const std::string dir = "probe_test_output_" + std::to_string(test::comm().size());
  const std::string path = dir + "/probe_block_probes.csv";
  ProbeRecorder rec(solver, {probe("tip", 0.375, 0.375)}, path);
  rec.record(solver);
  const auto start = rec.samples()[0].x;
  int rows = 1;
  while (solver.time() < s.time.end * (1 - 1e-12)) {
    solver.advance(s.time.end);
    rec.record(solver);
    ++rows;
    const double t = solver.time();
    for (int d = 0; d < 2; ++d) {
      ASSERT_NEAR(rec.samples()[0].u[d], kV[d] * t, 1e-12) << "step " << solver.stepCount();
      ASSERT_NEAR(rec.samples()[0].x[d], start[d] + kV[d] * t, 1e-12);
    }
  }
  // The block crossed the rank border at 0.5 (on 4 ranks its particles migrated).
  EXPECT_GT(rec.samples()[0].x[0], 0.5);
  EXPECT_GT(rec.samples()[0].x[1], 0.5);
  if (test::comm().root()) {
    std::ifstream in(path);
    std::string header, line, last;
    std::getline(in, header);
    EXPECT_EQ(header, "step,time,tip_x,tip_y,tip_ux,tip_uy");
    int n = 0;
    while (std::getline(in, line)) {
      last = line;
      ++n;
    }
    EXPECT_EQ(n, rows);
    double step = 0, time = 0, x = 0, y = 0, ux = 0, uy = 0;
    ASSERT_EQ(std::sscanf(last.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &step, &time, &x, &y, &ux, &uy), 6);
    EXPECT_EQ(step, double(solver.stepCount()));
    EXPECT_NEAR(time, s.time.end, 1e-12);
    EXPECT_NEAR(ux, kV[0] * s.time.end, 1e-10);
    EXPECT_NEAR(uy, kV[1] * s.time.end, 1e-10);
    std::filesystem::remove_all(dir);
  }
}

TEST(ProbeRecorder, NoneWithoutProbesOrWithOutputDisabled) {
  core::Scene s = movingBlock();
  s.output.directory = "probe_test_unused";
  {
    MpmSolver solver(s, test::comm());
    EXPECT_EQ(ProbeRecorder::fromScene(solver), nullptr);
  }
  s.output.probes = {probe("tip", 0.375, 0.375)};
  s.output.enabled = false;
  MpmSolver solver(s, test::comm());
  EXPECT_EQ(ProbeRecorder::fromScene(solver), nullptr);
  EXPECT_EQ(ProbeRecorder::pathFor(s), "probe_test_unused/probe_block_probes.csv");
  EXPECT_FALSE(std::filesystem::exists("probe_test_unused"));
}
