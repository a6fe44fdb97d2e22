// The sequential workflow with files: the force export format (src/core/io/force_export_file.h),
// its errors (file, line, what was expected), the `file` load's scene keys and the load mapped
// onto a flap's surface particles (src/couplings/surface/solid/file_load.h), total force and
// moment kept, on any number of ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/force_export_file.h"
#include "core/scene/scene.h"
#include "couplings/surface/solid/file_load.h"
#include "mpm/solver/mpm_solver.h"
#include "test_comm.h"

using namespace mpmice;

namespace {

// The head of the slides' CFX-Post export (two phases: air and water), abridged.
const char* kCfx = R"(#
# CFX-Post data export file
# Format used:
#   Floats to be displayed with a precision of: 3
#
# The following variables will be output for all locators:
# 1 - X [m]
# 2 - Y [m]
# 3 - Z [m]
# 4 - Air at 25 C.Force X [N]
# 5 - Air at 25 C.Force Y [N]
# 6 - Air at 25 C.Force Z [N]
# 7 - Water at 25 C.Force X [N]
# 8 - Water at 25 C.Force Y [N]
# 9 - Water at 25 C.Force Z [N]
#
1.866e-01, 2.550e-01, -8.884e-02, 2.812e-03, -1.276e-05, -2.819e-03, 5.996e-02, -1.464e-03, -6.835e-02
1.866e-01, 2.780e-01, -8.890e-02, -2.301e-05, -1.924e-07, 2.247e-05, 2.416e-02, -9.646e-04, -3.100e-02

2.036e-01, 2.681e-01, -7.193e-02, -9.754e-04, -1.321e-06, 9.594e-04, 4.697e-02, -1.717e-03, -5.895e-02
)";

std::string errorOf(const std::string& text) {
  try {
    (void)core::parseForceExport(text, "forces.csv");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string dir() {
  const std::string d = MPMICE_IO_TEST_DIR;
  std::filesystem::create_directories(d);
  return d;
}

core::Scene flapWithFileLoad(const std::string& file, const std::string& extra = "") {
  return core::parseScene(R"(
mesh: {dim: 2, lower: [-0.5, 0], upper: [0.5, 1.2], spacing: [0.025, 0.025]}
time: {end: 1}
materials:
  - {name: flap, kind: solid, density: 3000, model: {type: neo_hookean, youngs_modulus: 4.0e6, poissons_ratio: 0.3}}
geometry:
  - {shape: {type: box, lo: [-0.05, 0], hi: [0.05, 1]}, material: flap, particles_per_cell: [2, 2]}
loads:
  - {type: file, material: flap, file: )" + file + extra + R"(}
)", dir() + "/flap.yaml");
}

}  // namespace

TEST(ForceExport, ReadsTheSlidesCfxExportSummingThePhases) {
  const core::ForceExport e = core::parseForceExport(kCfx, "mixer.csv");
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e.phases, 2);
  EXPECT_EQ(e.depth, 0.0);
  EXPECT_DOUBLE_EQ(e.points[3], 1.866e-01);
  EXPECT_DOUBLE_EQ(e.points[8], -7.193e-02);
  // The slides' Nastran FORCE card of grid 1: 6.2671953114E-02 (air + water, x).
  EXPECT_NEAR(e.forces[0], 2.812e-03 + 5.996e-02, 1e-15);
  EXPECT_NEAR(e.forces[5], 2.247e-05 - 3.100e-02, 1e-15);
  const auto F = e.totalForce();
  EXPECT_NEAR(F[1], -1.276e-05 - 1.464e-03 - 1.924e-07 - 9.646e-04 - 1.321e-06 - 1.717e-03, 1e-15);
  // Moment about the origin of one point force: r x f.
  core::ForceExport one;
  one.points = {1, 2, 0};
  one.forces = {0, 0, 3};
  const auto M = one.totalMoment({0, 0, 0});
  EXPECT_DOUBLE_EQ(M[0], 6);
  EXPECT_DOUBLE_EQ(M[1], -3);
  EXPECT_DOUBLE_EQ(M[2], 0);
}

TEST(ForceExport, DepthComment) {
  const auto e = core::parseForceExport("# Depth [m]: 0.1\n0, 0.5, 0.05, 1, 2, 0\n", "f.csv");
  EXPECT_DOUBLE_EQ(e.depth, 0.1);
  EXPECT_EQ(e.phases, 1);
  EXPECT_NE(errorOf("# Depth [m]: -2\n0, 0, 0, 1, 2, 0\n").find("forces.csv:1: expected a depth > 0"), std::string::npos);
}

TEST(ForceExport, ErrorsNameTheFileTheLineAndWhatWasExpected) {
  struct Case {
    std::string text, expected;
  };
  const std::vector<Case> cases = {
      {"# h\n1, 2, 3, 4, x5, 6\n", "forces.csv:2: column 5: expected a number, got 'x5'"},
      {"1, 2, 3, 4, , 6\n", "forces.csv:1: column 5: expected a number, got ''"},
      {"1, 2, 3, 4, 5\n", "forces.csv:1: expected x, y, z and one force vector per fluid phase (3 + 3k numbers, k >= 1), got 5"},
      {"1, 2, 3\n", "got 3 numbers"},
      {"1, 2, 3, 4, 5, 6\n\n1, 2, 3, 4, 5, 6, 7, 8, 9\n", "forces.csv:3: expected 6 numbers as on line 1, got 9"},
      {"1, 2, 3, 4, nan, 6\n", "forces.csv:1: column 5: expected a finite number, got 'nan'"},
      {"1, 2, 3, 4, 1e999, 6\n", "forces.csv:1: column 5: expected a number, got '1e999'"},
      {"1; 2; 3; 4; 5; 6\n", "forces.csv:1: column 1: expected a number, got '1; 2; 3; 4; 5; 6'"},
      {"# only comments\n#\n", "forces.csv:2: expected data lines"},
      {"", "forces.csv:0: expected data lines"},
  };
  for (const auto& c : cases) {
    const std::string m = errorOf(c.text);
    EXPECT_NE(m.find(c.expected), std::string::npos) << "text:\n" << c.text << "\nerror: " << m;
  }
  try {
    (void)core::readForceExport(dir() + "/no_such_file.csv");
    FAIL() << "a missing file must be an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_file.csv: cannot open the force export file"), std::string::npos);
  }
}

TEST(FileLoadScene, KeysAndErrors) {
  const core::Scene s = flapWithFileLoad("forces.csv", ", mapping: nearest_neighbor, depth: 0.1");
  ASSERT_EQ(s.loads.size(), 1u);
  EXPECT_EQ(s.loads[0].type, core::LoadType::File);
  EXPECT_EQ(s.loads[0].file, "forces.csv");
  EXPECT_EQ(s.loads[0].mapping, core::InterfaceMapping::NearestNeighbor);
  EXPECT_DOUBLE_EQ(s.loads[0].depth, 0.1);
  try {
    (void)flapWithFileLoad("forces.csv", ", shape: {type: box, lo: [0, 0], hi: [1, 1]}");
    FAIL() << "a file load takes no shape";
  } catch (const core::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("shape"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)flapWithFileLoad("forces.csv", ", mapping: spline"), core::SceneError);
  EXPECT_THROW((void)flapWithFileLoad("forces.csv", ", depth: -1"), core::SceneError);
}

TEST(FileLoad, MapsConservativelyOntoTheSurfaceKeepingForceAndMoment) {
  // Forces on the flap's right face (x = 0.05), a 2D case of depth 0.1 m: a linear pressure-like
  // profile plus a shear, as OpenFOAM's export would give them at face centres (z = mid-depth).
  const std::string path = dir() + "/flap_forces_" + std::to_string(test::comm().size()) + ".csv";
  if (test::comm().root()) {
    std::ofstream f(path);
    f << "# test export\n# Depth [m]: 0.1\n";
    f.precision(17);
    for (int k = 0; k < 17; ++k) {
      const double y = (k + 0.5) / 17.0;
      f << 0.05 << ", " << y << ", " << 0.05 << ", " << -(2.0 - y) << ", " << 0.3 * y << ", " << 0.0 << "\n";
    }
  }
  MPI_Barrier(test::comm().raw());
  for (const char* mapping : {"rbf", "nearest_neighbor"}) {
    const core::Scene s = flapWithFileLoad(path, std::string(", mapping: ") + mapping + ", moment_center: [0, 0]");
    mpm::MpmSolver mpm(s, test::comm());
    std::ostringstream log;
    const auto reports = coupler::applyFileLoads(mpm, log);
    ASSERT_EQ(reports.size(), 1u);
    const auto& r = reports[0];
    EXPECT_EQ(r.points, 17u);
    EXPECT_EQ(r.particles, 172);
    EXPECT_DOUBLE_EQ(r.depth, 0.1);
    // Force read: sum -(2 - y) and 0.3 y over the 17 points.
    EXPECT_NEAR(r.forceRead[0], -(2.0 * 17 - 17 * 0.5), 1e-12);
    EXPECT_NEAR(r.forceRead[1], 0.3 * 17 * 0.5, 1e-12);
    for (int d = 0; d < 2; ++d) EXPECT_NEAR(r.forceApplied[d], r.forceRead[d], 1e-12 * 30) << mapping << " d " << d;
    if (std::string(mapping) == "rbf") {  // the linear polynomial keeps the moment
      EXPECT_NEAR(r.momentApplied[2], r.momentRead[2], 1e-10 * std::fabs(r.momentRead[2])) << log.str();
    }
    // What the particles hold: per metre of depth, summed over the ranks.
    const auto& p = mpm.particles();
    std::vector<double> held(2, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i)
      for (int d = 0; d < 2; ++d) held[d] += p.fsurf[d][i];
    test::comm().sumInPlace(held);
    for (int d = 0; d < 2; ++d) EXPECT_NEAR(held[d] * 0.1, r.forceRead[d], 1e-11) << mapping;
    if (test::comm().root()) {
      EXPECT_NE(log.str().find("read   : force ("), std::string::npos) << log.str();
      EXPECT_NE(log.str().find("applied: force ("), std::string::npos) << log.str();
    }
  }
}

TEST(FileLoad, BadFileStopsTheSolverNamingIt) {
  const std::string path = dir() + "/bad_forces_" + std::to_string(test::comm().size()) + ".csv";
  if (test::comm().root()) std::ofstream(path) << "# h\n0, 0.5, 0, 1, 2\n";
  MPI_Barrier(test::comm().raw());
  mpm::MpmSolver mpm(flapWithFileLoad(path), test::comm());
  std::ostringstream log;
  try {
    (void)coupler::applyFileLoads(mpm, log);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(":2: expected x, y, z"), std::string::npos) << e.what();
  }
}
