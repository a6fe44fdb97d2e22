// The study tool's pieces: grid expansion (order, count), key paths (parse, set, every error names
// the path), the study file (each bad input an error naming the file and the key), variants
// checked by the scene schema, the closing-line parser, the Pareto front, the reference registry.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/scene/scene.h"

#include "study/factors.h"
#include "study/grid.h"
#include "study/key_path.h"
#include "study/pareto.h"
#include "study/point_run.h"
#include "study/reference/piston.h"
#include "study/reference/probe_curve.h"
#include "study/reference/references.h"
#include "study/reference/shock_slab.h"
#include "study/study_file.h"
#include "study/study_run.h"

namespace fs = std::filesystem;
using namespace mpmice::study;

namespace {

Axis axis(const std::string& key, const std::vector<std::string>& values) {
  Axis a{key, {}};
  for (const auto& v : values) a.values.push_back(YAML::Load(v));
  return a;
}

std::string values(const Point& p) {
  std::string s;
  for (const auto& [k, v] : p.settings) {
    if (!s.empty()) s.push_back(',');
    s.append(valueText(v));
  }
  return s;
}

/// A study file in a fresh folder under the test's temp dir, with `body` after the common head.
class StudyFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("test_study_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& body, const std::string& head = "") {
    const std::string file = (dir_ / "s.yaml").string();
    std::ofstream(file) << (head.empty() ? "scene: " + std::string(TINY_CYLINDER) + "\nreference: lame_cylinder\n" : head)
                        << body;
    return file;
  }
  /// The StudyError message of reading `file` and dry-running it (variants checked).
  std::string errorOf(const std::string& file) {
    try {
      const Study s = readStudy(file);
      StudyOptions o;
      o.out = (dir_ / "out").string();
      o.dryRun = true;
      std::ostringstream out, err;
      runStudy(s, o, out, err);
    } catch (const StudyError& e) {
      return e.what();
    }
    return "";
  }
  /// `body` as a whole study file is refused by readStudy with an error that starts with the file
  /// and holds `key` and `says`.
  void expectRefused(const std::string& body, const std::string& key, const std::string& says) {
    const std::string f = write(body, "# a bad study\n");
    try {
      (void)readStudy(f);
      ADD_FAILURE() << "accepted:\n" << body;
    } catch (const StudyError& e) {
      const std::string w = e.what();
      EXPECT_EQ(w.rfind(f + ": ", 0), 0u) << w;
      EXPECT_NE(w.find(key), std::string::npos) << w;
      EXPECT_NE(w.find(says), std::string::npos) << w;
    }
  }
  fs::path dir_;
};

}  // namespace

TEST(Grid, FullGridFirstAxisSlowest) {
  const auto pts = expandGrid({axis("mesh.spacing", {"0.05", "0.025"}), axis("mpm.shape_function", {"linear", "gimp", "bspline2"})});
  ASSERT_EQ(pts.size(), 6u);
  const std::vector<std::string> want{"0.05,linear", "0.05,gimp", "0.05,bspline2",
                                      "0.025,linear", "0.025,gimp", "0.025,bspline2"};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(values(pts[i]), want[i]) << "point " << i;
    ASSERT_EQ(pts[i].settings.size(), 2u);
    EXPECT_EQ(pts[i].settings[0].first, "mesh.spacing");
    EXPECT_EQ(pts[i].settings[1].first, "mpm.shape_function");
  }
}

TEST(Grid, ThreeAxesCountAndLastFastest) {
  const auto pts = expandGrid({axis("a", {"1", "2"}), axis("b", {"x", "y"}), axis("c", {"p", "q", "r"})});
  ASSERT_EQ(pts.size(), 12u);
  EXPECT_EQ(values(pts[0]), "1,x,p");
  EXPECT_EQ(values(pts[1]), "1,x,q");
  EXPECT_EQ(values(pts[3]), "1,y,p");
  EXPECT_EQ(values(pts[6]), "2,x,p");
  EXPECT_EQ(values(pts[11]), "2,y,r");
}

TEST(Grid, NoAxesIsTheBaseAndAnEmptyAxisIsAnError) {
  const auto pts = expandGrid({});
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_TRUE(pts[0].settings.empty());
  EXPECT_EQ(pointLabel(pts[0]), "base");
  try {
    (void)expandGrid({axis("mesh.spacing", {})});
    FAIL() << "an axis without values was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mesh.spacing"), std::string::npos) << e.what();
  }
}

TEST(Grid, LabelsAndFolders) {
  const auto pts = expandGrid({axis("mesh.spacing", {"0.025"}), axis("coupling.acceleration", {"{type: aitken, relaxation: 0.5}"})});
  EXPECT_EQ(pointLabel(pts[0]), "0.025 / {type: aitken, relaxation: 0.5}");
  EXPECT_EQ(pointFolder(pts[0], 7), "007_0.025__type__aitken__relaxation__0.5_");
}

TEST(KeyPath, Parses) {
  const auto s = parseKeyPath("geometry[wall].particles_per_cell");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].key, "geometry");
  ASSERT_TRUE(s[0].select);
  EXPECT_EQ(*s[0].select, "wall");
  EXPECT_EQ(s[1].key, "particles_per_cell");
  EXPECT_FALSE(s[1].select);
  EXPECT_EQ(parseKeyPath("mesh.spacing").size(), 2u);
}

TEST(KeyPath, SyntaxErrorsNameThePath) {
  for (const std::string bad : {"", "mesh..spacing", "mesh.", ".mesh", "geometry[wall", "geometry[].x", "geometry[wall]x"}) {
    try {
      (void)parseKeyPath(bad);
      ADD_FAILURE() << "'" << bad << "' was accepted";
    } catch (const KeyPathError& e) {
      EXPECT_NE(std::string(e.what()).find("key path '" + bad + "'"), std::string::npos) << e.what();
      EXPECT_EQ(e.path(), bad);
    }
  }
}

TEST(KeyPath, SetsMappingsListElementsAndCreatesKeys) {
  YAML::Node scene = YAML::LoadFile(TINY_CYLINDER);
  setKeyPath(scene, "mesh.spacing", YAML::Load("0.05"));
  setKeyPath(scene, "mpm.update", YAML::Load("musl"));                 // absent in the scene: created
  setKeyPath(scene, "geometry[wall].particles_per_cell", YAML::Load("4"));
  setKeyPath(scene, "geometry[0].temperature", YAML::Load("310"));
  setKeyPath(scene, "coupling.acceleration", YAML::Load("{type: aitken, relaxation: 0.5}"));
  setKeyPath(scene, "ice.limiter", YAML::Load("minmod"));
  EXPECT_EQ(scene["mesh"]["spacing"].as<double>(), 0.05);
  EXPECT_EQ(scene["mesh"]["dim"].as<int>(), 2);  // the rest untouched
  EXPECT_EQ(scene["mpm"]["update"].as<std::string>(), "musl");
  EXPECT_EQ(scene["mpm"]["shape_function"].as<std::string>(), "linear");
  EXPECT_EQ(scene["geometry"][1]["particles_per_cell"].as<int>(), 4);
  EXPECT_EQ(scene["geometry"][1]["name"].as<std::string>(), "wall");
  EXPECT_EQ(scene["geometry"][0]["temperature"].as<double>(), 310);
  EXPECT_EQ(scene["geometry"].size(), 2u);
  EXPECT_EQ(scene["coupling"]["acceleration"]["type"].as<std::string>(), "aitken");
  EXPECT_EQ(scene["coupling"]["schedule"].as<std::string>(), "monolithic");
  EXPECT_EQ(scene["ice"]["limiter"].as<std::string>(), "minmod");
  // The edited scene is still a valid scene.
  YAML::Emitter e;
  e << scene;
  EXPECT_NO_THROW((void)mpmice::core::parseScene(e.c_str(), "edited.yaml"));
}

TEST(KeyPath, PathsThatDoNotFitTheSceneNameThePathAndWhatIsThere) {
  const YAML::Node base = YAML::LoadFile(TINY_CYLINDER);
  struct Case {
    std::string path, says;
  };
  for (const Case& c : {Case{"geometry[pipe].particles_per_cell", "no element of 'geometry' is named 'pipe' (named: air, wall)"},
                        Case{"geometry[5].particles_per_cell", "'geometry' has 2 elements; no index 5"},
                        Case{"mesh[wall].spacing", "'mesh' is a mapping, not a list"},
                        Case{"mesh.spacing.x", "'mesh.spacing' is a scalar, not a mapping"},
                        Case{"loads[wall].x", "the scene has no list 'loads'"}}) {
    YAML::Node scene = YAML::Clone(base);
    try {
      setKeyPath(scene, c.path, YAML::Load("1"));
      ADD_FAILURE() << c.path << " was accepted";
    } catch (const KeyPathError& e) {
      EXPECT_NE(std::string(e.what()).find("key path '" + c.path + "'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}

TEST_F(StudyFileTest, ReadsAGridAndAnExplicitList) {
  Study s = readStudy(write("time_limit: 30\nrepeats: 2\nset: {time.end: 1.0e-5}\naxes:\n  mesh.spacing: [0.1, 0.05]\n"
                            "  geometry[wall].particles_per_cell: [2, 3, 4]\n"));
  EXPECT_EQ(s.name, "s");
  EXPECT_EQ(s.program, Program::Mpmice);
  EXPECT_EQ(s.timeLimit, 30);
  EXPECT_EQ(s.repeats, 2);
  EXPECT_EQ(s.cost, Cost::Wall);  // the default
  EXPECT_EQ(readStudy(write("cost: cpu\naxes: {mesh.spacing: [0.1]}\n")).cost, Cost::Cpu);
  EXPECT_EQ(s.points.size(), 6u);
  EXPECT_EQ(s.columns, (std::vector<std::string>{"mesh.spacing", "geometry[wall].particles_per_cell"}));
  const YAML::Node v = variantScene(s, YAML::LoadFile(TINY_CYLINDER), s.points[5], "/tmp/run5");
  EXPECT_EQ(v["mesh"]["spacing"].as<double>(), 0.05);
  EXPECT_EQ(v["geometry"][1]["particles_per_cell"].as<int>(), 4);
  EXPECT_EQ(v["time"]["end"].as<double>(), 1.0e-5);
  EXPECT_EQ(v["output"]["directory"].as<std::string>(), "/tmp/run5");

  s = readStudy(write("study: pts\nprogram: coupler_run\npoints:\n  - {mpm.shape_function: bspline2}\n"
                      "  - {coupling.schedule: explicit_parallel, coupling.ranks.mpm: 2}\n"));
  EXPECT_EQ(s.name, "pts");
  EXPECT_EQ(s.program, Program::CouplerRun);
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_EQ(s.columns, (std::vector<std::string>{"mpm.shape_function", "coupling.schedule", "coupling.ranks.mpm"}));
  StudyOptions o;
  o.binDir = "/b";
  EXPECT_EQ(pointCommand(s, s.points[1], "x.yaml", o),
            (std::vector<std::string>{"/b/coupler/coupler", "run", "--bin-dir", "/b", "x.yaml"}));
}

TEST_F(StudyFileTest, OneFactorAtATimeThenSlicesEachPointOnce) {
  const Study s = readStudy(write(
      "base: {time.cfl: 0.4, coupling.schedule: monolithic, coupling.acceleration.type: none}\n"
      "factors:\n"
      "  time.cfl: [0.1, 0.7]\n"
      "  schedule:\n"
      "    - {coupling.schedule: implicit_serial, coupling.acceleration.type: iqn_ils}\n"
      "    - {coupling.schedule: explicit_serial}\n"
      "slices:\n"
      "  - {time.cfl: [0.1, 0.4], schedule: all}\n"));
  // base, 2 cfl levels, 2 schedules, then the 2 x 2 slice less the two points it shares with the factors.
  std::vector<std::string> got;
  for (const auto& p : s.points) got.push_back(values(p));
  EXPECT_EQ(got, (std::vector<std::string>{"0.4,monolithic,none", "0.1,monolithic,none", "0.7,monolithic,none",
                                            "0.4,implicit_serial,iqn_ils", "0.4,explicit_serial,none",
                                            "0.1,implicit_serial,iqn_ils", "0.1,explicit_serial,none"}));
  EXPECT_EQ(s.columns, (std::vector<std::string>{"time.cfl", "coupling.schedule", "coupling.acceleration.type"}));
  const YAML::Node v = variantScene(s, YAML::LoadFile(TINY_CYLINDER), s.points[3], "/tmp/run3");
  EXPECT_EQ(v["coupling"]["schedule"].as<std::string>(), "implicit_serial");
  EXPECT_EQ(v["time"]["cfl"].as<double>(), 0.4);
}

TEST(Factors, TheBaseIsNotRewrittenByTheLevels) {
  // yaml-cpp's Node assignment rewrites the node shared with the base: the expansion must not use it.
  const Settings base{{"time.cfl", YAML::Load("0.4")}};
  const auto pts = expandFactors(base, {Factor{"time.cfl", {{{"time.cfl", YAML::Load("0.1")}}}}}, {});
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(values(pts[0]), "0.4");
  EXPECT_EQ(values(pts[1]), "0.1");
  EXPECT_EQ(valueText(base[0].second), "0.4");
  EXPECT_THROW((void)expandFactors(base, {Factor{"k", {{{"mesh.spacing", YAML::Load("1")}}}}}, {}), std::invalid_argument);
}

TEST_F(StudyFileTest, OneFactorAtATimeBadInputNamesTheFileAndTheKey) {
  const std::string head = "scene: " + std::string(TINY_CYLINDER) + "\nreference: lame_cylinder\n";
  struct Case {
    std::string body, key, says;
  };
  for (const Case& c : {
           Case{"factors: {time.cfl: [0.1]}\n", "'base'", "required with `factors`"},
           Case{"base: {time.cfl: 0.4}\naxes: {mesh.spacing: [0.1]}\n", "'base'", "`factors` is missing"},
           Case{"base: {time.cfl: 0.4}\nfactors: {mesh.spacing: [0.1]}\n", "'factors'", "'mesh.spacing' is not in `base`"},
           Case{"base: {time.cfl: 0.4}\nfactors: {time.cfl: []}\n", "'factors.time.cfl'", "non-empty list"},
           Case{"base: {time.cfl: 0.4}\nfactors: {ice: [first_order]}\n", "factor 'ice'", "key 'ice' is not in `base`"},
           Case{"base: {time.cfl: 0.4}\nfactors: {fast..one: [0.1]}\n", "'factors.fast..one[0]'", "must be a mapping"},
           Case{"base: {time.cfl: 0.4, mesh.spacing: 0.1}\nfactors: {time.cfl: [0.1]}\nslices: [{time.cfl: all}]\n",
                "'slices[0]'", "two or more factors"},
           Case{"base: {time.cfl: 0.4, mesh.spacing: 0.1}\nfactors: {time.cfl: [0.1]}\n"
                "slices: [{time.cfl: all, spacing: all}]\n", "'slices[0].spacing'", "`all` needs a factor"},
           Case{"base: {time.cfl: 0.4}\nfactors: {time.cfl: [0.1]}\npoints: [{time.cfl: 0.2}]\n", "'points'", "not both"},
       }) {
    expectRefused(head + c.body, c.key, c.says);
  }
}

TEST_F(StudyFileTest, RanksRunMpmiceUnderTheLaunchHelper) {
  const Study s = readStudy(write("axes: {ranks: [1, 2]}\n"));
  StudyOptions o;
  o.binDir = "/b";
  o.mpirun = "/s/mpirun";
  EXPECT_EQ(pointCommand(s, s.points[0], "x.yaml", o), (std::vector<std::string>{"/b/coupler/mpmice", "x.yaml"}));
  EXPECT_EQ(pointCommand(s, s.points[1], "x.yaml", o),
            (std::vector<std::string>{"/s/mpirun", "-np", "2", "/b/coupler/mpmice", "x.yaml"}));
}

TEST_F(StudyFileTest, ABadKeyPathIsAnErrorNamingTheKeyAndTheStudyFile) {
  const std::string f = write("axes:\n  geometry[pipe].particles_per_cell: [2, 4]\n");
  const std::string e = errorOf(f);
  EXPECT_NE(e.find(f), std::string::npos) << e;
  EXPECT_NE(e.find("geometry[pipe].particles_per_cell"), std::string::npos) << e;
  EXPECT_NE(e.find("named: air, wall"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(dir_ / "out"));  // nothing created
  // A syntax error is found when the file is read.
  const std::string g = write("axes:\n  mesh..spacing: [0.1]\n");
  const std::string e2 = errorOf(g);
  EXPECT_NE(e2.find(g), std::string::npos) << e2;
  EXPECT_NE(e2.find("mesh..spacing"), std::string::npos) << e2;
}

TEST_F(StudyFileTest, AKeyTheSceneDoesNotKnowIsAnErrorNamingTheKeyAndTheStudyFile) {
  const std::string f = write("axes:\n  mpm.shape_functon: [linear]\n");
  const std::string e = errorOf(f);
  EXPECT_NE(e.find(f), std::string::npos) << e;
  EXPECT_NE(e.find("mpm.shape_functon"), std::string::npos) << e;
  EXPECT_NE(e.find("invalid scene"), std::string::npos) << e;
  // A value the scene refuses: the point and its settings are named.
  const std::string g = write("axes:\n  mpm.shape_function: [linear, quartic]\n");
  const std::string e2 = errorOf(g);
  EXPECT_NE(e2.find(g + ": point 2 (mpm.shape_function: quartic)"), std::string::npos) << e2;
}

TEST_F(StudyFileTest, AProbeCurveReferenceReadsItsCurveRelativeToTheStudyFile) {
  std::ofstream(dir_ / "tip.csv") << "# reference\nstep,time,tip_ux\n0,0,0\n1,0.01,0.001\n";
  const std::string head = "scene: " + std::string(TINY_CYLINDER) + "\nreference: probe_curve\n";
  const Study s = readStudy(write("reference_curve: tip.csv\nreference_column: tip_ux\naxes: {mesh.spacing: [0.1]}\n", head));
  EXPECT_EQ(s.referenceCurve, (dir_ / "tip.csv").lexically_normal().string());
  EXPECT_EQ(s.referenceColumn, "tip_ux");
  struct Case {
    std::string body, key, says;
  };
  for (const Case& c : {
           Case{head + "reference_column: tip_ux\naxes: {mesh.spacing: [0.1]}\n", "'reference_curve'", "required with the reference probe_curve"},
           Case{head + "reference_curve: tip.csv\naxes: {mesh.spacing: [0.1]}\n", "'reference_column'", "required with the reference probe_curve"},
           Case{head + "reference_curve: none.csv\nreference_column: tip_ux\naxes: {mesh.spacing: [0.1]}\n", "'reference_curve'", "none.csv: cannot read the file"},
           Case{head + "reference_curve: tip.csv\nreference_column: tip_uy\naxes: {mesh.spacing: [0.1]}\n", "'reference_curve'", "no column 'tip_uy'"},
           Case{"scene: " + std::string(TINY_CYLINDER) + "\nreference: lame_cylinder\nreference_curve: tip.csv\naxes: {mesh.spacing: [0.1]}\n",
                "'reference_curve'", "only a reference that reads a curve takes it (probe_curve); this study's is lame_cylinder"},
       }) {
    expectRefused(c.body, c.key, c.says);
  }
  std::ofstream(dir_ / "one.csv") << "time,tip_ux\n0,0\n";
  EXPECT_NE(errorOf(write("reference_curve: one.csv\nreference_column: tip_ux\naxes: {mesh.spacing: [0.1]}\n", head))
                .find("at least 2 rows"),
            std::string::npos);
}

TEST_F(StudyFileTest, BadInputNamesTheFileAndTheKey) {
  const std::string head = "scene: " + std::string(TINY_CYLINDER) + "\n";
  struct Case {
    std::string body, key, says;
  };
  for (const Case& c : {
           Case{head + "reference: lame_cylinder\naxes: {mesh.spacing: [0.1]}\ncolour: red\n", "'colour'", "unknown key"},
           Case{head + "reference: piston_exact\naxes: {mesh.spacing: [0.1]}\n", "'reference'", "valid: lame_cylinder"},
           Case{head + "axes: {mesh.spacing: [0.1]}\n", "'reference'", "required"},
           Case{"reference: lame_cylinder\naxes: {mesh.spacing: [0.1]}\n", "'scene'", "required"},
           Case{"scene: nowhere.yaml\nreference: lame_cylinder\naxes: {mesh.spacing: [0.1]}\n", "'scene'", "no scene file"},
           Case{head + "reference: lame_cylinder\nprogram: mpirun\naxes: {mesh.spacing: [0.1]}\n", "'program'", "valid: mpmice, coupler_run"},
           Case{head + "reference: lame_cylinder\ntime_limit: 0\naxes: {mesh.spacing: [0.1]}\n", "'time_limit'", "> 0"},
           Case{head + "reference: lame_cylinder\nrepeats: 0\naxes: {mesh.spacing: [0.1]}\n", "'repeats'", ">= 1"},
           Case{head + "reference: lame_cylinder\ncost: gpu\naxes: {mesh.spacing: [0.1]}\n", "'cost'", "valid: wall, cpu"},
           Case{head + "reference: lame_cylinder\naxes: {mesh.spacing: []}\n", "'axes.mesh.spacing'", "non-empty list"},
           Case{head + "reference: lame_cylinder\naxes: {mesh.spacing: 0.1}\n", "'axes.mesh.spacing'", "non-empty list"},
           Case{head + "reference: lame_cylinder\n", "'axes'", "required"},
           Case{head + "reference: lame_cylinder\naxes: {mesh.spacing: [0.1]}\npoints: [{mesh.spacing: 0.1}]\n", "'points'", "not both"},
           Case{head + "reference: lame_cylinder\nprogram: coupler_run\naxes: {ranks: [1, 2]}\n", "'ranks'", "coupling.ranks.mpm"},
           Case{head + "reference: lame_cylinder\naxes: {ranks: [0]}\n", "'ranks'", ">= 1"},
       }) {
    expectRefused(c.body, c.key, c.says);
  }
}

TEST(RunLog, ClosingLinesGiveStepsAndIterations) {
  const std::string mpmice =
      "step 100 t = ...\ncoupling: schedule implicit_serial, 1234 iterations in 617 steps (2.0000 per step), 0 steps "
      "accepted unconverged\ndone: 617 steps, t = 4.000e-03 s, wall 9.9 s\n";
  RunCounts c = parseRunLog(mpmice);
  EXPECT_EQ(c.steps, 617);
  EXPECT_DOUBLE_EQ(c.iterationsPerStep, 2.0);
  c = parseRunLog("done: 42 steps, t = 1.0e-3 s, wall 1 s\n");
  EXPECT_EQ(c.steps, 42);
  EXPECT_EQ(c.iterationsPerStep, -1);
  c = parseRunLog("mpmice: error: the scene is broken\n");
  EXPECT_EQ(c.steps, -1);
}

TEST(RunLog, TheNoteOfAFailedRunIsOurLastLineNotOpenMpisBanner) {
  const std::string aborted =
      "step 12 t = 3.1e-5\n"
      "mpmice: health check: air at 1.05e9 K in cell (39,5,0) at t = 1.091e-03 s\n"
      "--------------------------------------------------------------------------\n"
      "MPI_ABORT was invoked on rank 0 in communicator MPI_COMM_WORLD\n"
      "  Proc: [[41020,1],0]\n"
      "  Errorcode: 1\n"
      "\n"
      "NOTE: invoking MPI_ABORT causes Open MPI to kill all MPI processes.\n"
      "You may or may not see output from the other processes, depending on\n"
      "exactly when Open MPI kills them.\n"
      "--------------------------------------------------------------------------\n"
      "[host:01234] 1 more process has sent help message help-mpi-api.txt / mpi-abort\n"
      "prterun has exited due to process rank 0 with PID 0 on node host calling\n";
  EXPECT_EQ(programNote(aborted), "mpmice: health check: air at 1.05e9 K in cell (39,5,0) at t = 1.091e-03 s");
  EXPECT_EQ(programNote("a\nconfigs/x.yaml:3: key 'mesh.spacing': -1 is not > 0\n\n"),
            "configs/x.yaml:3: key 'mesh.spacing': -1 is not > 0");
  const std::string onlyBanner = "-----------\nMPI_ABORT was invoked\n-----------\n";
  EXPECT_EQ(programNote(onlyBanner), "MPI_ABORT was invoked");
}

TEST(RunLog, AResultReadsBack) {
  PointResult r;
  r.status = "ok";
  r.exitCode = 0;
  r.wallSeconds = 2.5;
  r.walls = {2.4, 2.5, 3.1};
  r.cpuSeconds = 4.75;
  r.cpus = {4.5, 4.75, 6.0};
  r.peakRssMb = 31.25;
  r.steps = 99;
  r.iterationsPerStep = 1.5;
  r.error = 0.0843125;
  r.note = "a: b, c";
  const fs::path f = fs::temp_directory_path() / ("test_study_result_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(f) << resultYaml(r);
  const PointResult b = readResult(f.string());
  fs::remove(f);
  EXPECT_EQ(b.status, "ok");
  EXPECT_EQ(b.walls, r.walls);
  EXPECT_EQ(b.cpus, r.cpus);
  EXPECT_DOUBLE_EQ(b.cpuSeconds, 4.75);
  EXPECT_EQ(b.steps, 99);
  EXPECT_DOUBLE_EQ(b.error, 0.0843125);
  EXPECT_DOUBLE_EQ(b.iterationsPerStep, 1.5);
  EXPECT_EQ(b.note, r.note);
  r.error = NAN;
  r.status = "failed";
  std::ofstream(f) << resultYaml(r);
  EXPECT_TRUE(std::isnan(readResult(f.string()).error));
  // A result written before the CPU time was recorded reads back without one.
  std::ofstream(f) << "status: ok\nexit_code: 0\nwall_s: 2\npeak_rss_mb: 3\nsteps: 4\niterations_per_step: 1\nerror: 0.5\n";
  EXPECT_TRUE(std::isnan(readResult(f.string()).cpuSeconds));
  fs::remove(f);
}

TEST(Pareto, FrontIsTheUndominatedPointsFastestFirst) {
  const std::vector<TradePoint> pts{{"a", 10, 0.05}, {"b", 1, 0.2}, {"c", 2, 0.3}, {"d", 5, 0.1},
                                    {"e", 20, 0.06}, {"f", 3, NAN}, {"g", 0, 0.01}, {"h", 5, 0.08}};
  EXPECT_EQ(paretoFront(pts), (std::vector<std::size_t>{1, 7, 0}));  // b, h (beats d at equal cost), a
}

TEST(References, RegistryByNameAndTheValidChoices) {
  EXPECT_EQ(findReference("lame_cylinder").name, "lame_cylinder");
  EXPECT_EQ(findReference("piston").name, "piston");
  EXPECT_EQ(findReference("shock_slab").name, "shock_slab");
  EXPECT_EQ(findReference("probe_curve").name, "probe_curve");
  EXPECT_TRUE(findReference("probe_curve").readsCurve);
  EXPECT_FALSE(findReference("lame_cylinder").readsCurve);
  EXPECT_EQ(referenceNames(), "lame_cylinder, piston, shock_slab, probe_curve");
  try {
    (void)findReference("flap_reference_curve");
    FAIL() << "an unknown reference was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'flap_reference_curve' is not a reference (valid: lame_cylinder, piston, "
                                         "shock_slab, probe_curve)"),
              std::string::npos) << e.what();
  }
}

// probe_curve: the run's record interpolated at the reference's samples inside the run's span.
// A sine against the same sine shifted by a constant c: rms of the difference c, relative c / rms
// of the reference; a run sampled more coarsely than the reference (linear between its rows);
// a run shorter than the reference compared on its own span only.
TEST(References, ProbeCurveDifferenceOnTheReferencesSamplesInsideTheRun) {
  mpmice::core::TimeSeries ref, run, coarse, shortRun;
  for (int i = 0; i <= 500; ++i) {
    const double t = 0.01 * i;
    ref.t.push_back(t);
    ref.u.push_back(0.1 + 0.05 * std::sin(4 * t));
  }
  for (int i = 0; i <= 1000; ++i) {
    const double t = 0.005 * i + 0.001;  // other times than the reference's; starts after it
    run.t.push_back(t);
    run.u.push_back(0.1 + 0.05 * std::sin(4 * t) + 0.02);
  }
  const CurveDifference d = curveDifference(ref, run);
  EXPECT_EQ(d.samples, 500u);  // t = 0.01 .. 5.0: 0 is before the run's first row (0.001)
  EXPECT_NEAR(d.tFirst, 0.01, 1e-12);
  EXPECT_NEAR(d.tLast, 5.0, 1e-12);
  EXPECT_NEAR(d.mean, 0.02, 1e-4);  // the interpolation's error: 0.05 x 16 x 0.005^2 / 8
  EXPECT_NEAR(d.rms, 0.02, 1e-4);
  double r2 = 0;
  for (std::size_t i = 1; i <= 500; ++i) r2 += ref.u[i] * ref.u[i];
  EXPECT_NEAR(d.rmsReference, std::sqrt(r2 / 500), 1e-12);
  EXPECT_NEAR(d.relative(), 0.02 / d.rmsReference, 1e-4);
  // A linear record against a linear reference: exact however coarse.
  mpmice::core::TimeSeries lin, linRun;
  for (int i = 0; i <= 100; ++i) {
    lin.t.push_back(0.01 * i);
    lin.u.push_back(1 + 2 * 0.01 * i);
  }
  linRun.t = {0.0, 0.37, 1.0};
  linRun.u = {1.0 + 0.5, 1.74 + 0.5, 3.0 + 0.5};
  const CurveDifference l = curveDifference(lin, linRun);
  EXPECT_EQ(l.samples, 101u);
  EXPECT_NEAR(l.rms, 0.5, 1e-12);
  EXPECT_NEAR(l.largest, 0.5, 1e-12);
  // A run to 1 s against the 5 s reference: the first second only.
  for (std::size_t i = 0; i < run.t.size() && run.t[i] <= 1.0; ++i) {
    shortRun.t.push_back(run.t[i]);
    shortRun.u.push_back(run.u[i] - 0.02 + (run.t[i] > 0.5 ? 0.1 : 0.0));
  }
  const CurveDifference s = curveDifference(ref, shortRun);
  EXPECT_NEAR(s.tLast, 0.99, 1e-12);
  EXPECT_NEAR(s.largest, 0.1, 1e-3);
  EXPECT_GT(s.largestTime, 0.5);
}

TEST(References, ProbeCurveThatCannotBeComparedIsAnError) {
  mpmice::core::TimeSeries ref, run, zero;
  ref.t = {0.0, 1.0, 2.0};
  ref.u = {1.0, 1.0, 1.0};
  run.t = {2.5, 3.0};
  run.u = {1.0, 1.0};
  try {
    (void)curveDifference(ref, run);
    FAIL() << "no shared samples accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("holds 0 of the reference curve's samples"), std::string::npos) << e.what();
  }
  zero.t = ref.t;
  zero.u = {0.0, 0.0, 0.0};
  run.t = {0.0, 2.0};
  try {
    (void)curveDifference(zero, run);
    FAIL() << "a zero reference accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the reference curve is 0"), std::string::npos) << e.what();
  }
}

namespace mpmice::study {
namespace {

// The exact answers the `piston` and `shock_slab` references compare with, computed from the
// shipped scenes: the figures their comments (and docs/verification-coupled.md) quote.
TEST(References, PistonExactAnswerFromTheScene) {
  const PistonSetup e = pistonSetup(core::loadScene(PISTON_SCENE));
  EXPECT_DOUBLE_EQ(e.h0, 0.4);
  EXPECT_DOUBLE_EQ(e.hL0, 0.2);
  EXPECT_DOUBLE_EQ(e.M, 8900 * 0.4);
  // both gas columns at the quiet state, 101325 / (0.4 x 717.5 x 300) kg/m^3 over 0.6 m (their
  // inertia: a third of it moves with the piston)
  EXPECT_NEAR(e.gasMass, 101325.0 / (0.4 * 717.5 * 300) * 0.6, 1e-12);
  EXPECT_EQ(e.gas, "air");
  const PistonExact x = pistonExact(e, 0.02);
  EXPECT_NEAR(x.s, 0.19639, 1e-5);
  EXPECT_NEAR(x.v, 9.443, 1e-3);
  EXPECT_NEAR(x.p, 260.78e3, 10.0);
  EXPECT_NEAR(x.pL, 38.89e3, 10.0);
  // A piston that does not move leaves the gas at p0.
  EXPECT_DOUBLE_EQ(pistonExact(e, 0).p, e.p0);
}

TEST(References, ShockSlabExactAnswerFromTheScene) {
  const SlabExact e = slabExact(core::loadScene(SHOCK_SLAB_SCENE));
  EXPECT_NEAR(e.p5, 1.51988e6, 10.0);
  EXPECT_NEAR(e.Wr, 347.2, 0.1);
  EXPECT_NEAR(e.W, 694.38, 0.01);
  EXPECT_NEAR(e.cSolid, 5813.8, 0.1);
  EXPECT_NEAR(e.hitTime(), 0.4 / 694.38, 1e-8);
}

TEST(References, ASceneWithoutTheRegionsIsRefusedNamingTheFile) {
  try {
    (void)slabExact(core::loadScene(PISTON_SCENE));
    FAIL() << "the piston scene has no regions shocked / quiet / slab";
  } catch (const std::runtime_error& ex) {
    EXPECT_NE(std::string(ex.what()).find("no region 'shocked'"), std::string::npos) << ex.what();
    EXPECT_NE(std::string(ex.what()).find("piston.yaml"), std::string::npos) << ex.what();
  }
}

}  // namespace
}  // namespace mpmice::study
