// `coupler run`: the composed MPMD line and the translation of failed world ranks to participants.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unistd.h>

#include "coupler/cli/openfoam_case.h"
#include "coupler/cli/process.h"
#include "coupler/cli/program_locator.h"
#include "coupler/launch/timed_wait.h"
#include "coupler/cli/run_command.h"
#include "core/io/h5_file.h"
#include "core/scene/scene.h"

using namespace mpmice;

namespace {
core::Scene tinyScene() {
  return core::parseScene(R"(
scene: tiny
mesh: {dim: 2, lower: [0, 0], upper: [1, 1], cells: [4, 4]}
time: {end: 1.0e-3}
materials:
  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}
  - {name: steel, kind: solid, density: 8900, model: {type: linear_elastic, bulk_modulus: 117e9, shear_modulus: 43.8e9}}
geometry:
  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1.0e5, density: 1.2}
  - {shape: {type: box, lo: [0.25, 0.25], hi: [0.75, 0.75]}, material: steel}
coupling: {ranks: {mpm: 2, ice: 3}}
)", "tiny.yaml");
}

// A scene of one kind of material: one program, the other has nothing to solve.
core::Scene oneKindScene(bool solid) {
  std::string yaml = "scene: one\nmesh: {dim: 2, lower: [0, 0], upper: [1, 1], cells: [4, 4]}\ntime: {end: 1.0e-3}\n";
  yaml += solid ? "materials:\n  - {name: steel, kind: solid, density: 8900, model: {type: linear_elastic, "
                  "bulk_modulus: 117e9, shear_modulus: 43.8e9}}\ngeometry:\n  - {shape: {type: box, lo: [0.25, 0.25], "
                  "hi: [0.75, 0.75]}, material: steel}\n"
                : "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}\ngeometry:\n  - "
                  "{shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1.0e5, density: 1.2}\n";
  return core::parseScene(yaml + "coupling: {ranks: {mpm: 2, ice: 3}}\n", "one.yaml");
}
}  // namespace

TEST(CoupleRun, ASceneOfOneKindOfMaterialLaunchesOneProgram) {
  const auto solids = coupler::composeLaunch(oneKindScene(true), "one.yaml", "/b", "/x/mpirun", 2, 3);
  EXPECT_EQ(solids.commandLine(), "/x/mpirun -np 2 /b/mpm_solver/mpm_solver one.yaml");
  const auto fluids = coupler::composeLaunch(oneKindScene(false), "one.yaml", "/b", "/x/mpirun", 2, 3);
  EXPECT_EQ(fluids.commandLine(), "/x/mpirun -np 3 /b/ice_solver/ice_solver one.yaml");
  EXPECT_EQ(fluids.describeWorldRank(0), "ice_solver rank 0");
}

TEST(CoupleRun, ComposesMpmdLineFromSceneRanks) {
  const auto s = tinyScene();
  const auto plan = coupler::composeLaunch(s, "tiny.yaml", "/b", "/x/mpirun", s.coupling.mpm_ranks,
                                           s.coupling.ice_ranks);
  EXPECT_EQ(plan.commandLine(),
            "/x/mpirun -np 2 /b/mpm_solver/mpm_solver tiny.yaml : -np 3 /b/ice_solver/ice_solver tiny.yaml");
  EXPECT_EQ(plan.describeWorldRank(0), "mpm_solver rank 0");
  EXPECT_EQ(plan.describeWorldRank(2), "ice_solver rank 0");
  EXPECT_EQ(plan.describeWorldRank(4), "ice_solver rank 2");
  EXPECT_EQ(plan.describeWorldRank(5), "");
}

TEST(CoupleRun, RestartPassesThePathToBothPrograms) {
  const auto s = tinyScene();
  const auto plan = coupler::composeLaunch(s, "tiny.yaml", "/b", "/x/mpirun", 2, 3, "", "out dir");
  EXPECT_EQ(plan.commandLine(), "/x/mpirun -np 2 /b/mpm_solver/mpm_solver --restart 'out dir' tiny.yaml : -np 3 "
                                "/b/ice_solver/ice_solver --restart 'out dir' tiny.yaml");
  EXPECT_EQ(plan.argv.at(4), "--restart");
  EXPECT_EQ(plan.argv.at(5), "out dir");  // one argument, no shell
}

TEST(CoupleRun, ExplainsFailedRanksFromMpirunText) {
  const auto s = tinyScene();
  const auto plan = coupler::composeLaunch(s, "tiny.yaml", "/b", "mpirun", 1, 2);
  const std::string text =
      "mpirun noticed that process rank 2 with PID 123 on node vm exited on signal 9 (Killed).\n"
      "  Process name: [[4242,1],2]\n";
  const auto lines = coupler::explainFailure(plan, text);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "coupler: world rank 2 is ice_solver rank 1");
}

TEST(CoupleRun, AParticipantThatStoppedAnsweringIsNamedInTheClosingLine) {
  // mpm_solver timed out waiting for ice: the closing line names ice_solver (the one that stopped),
  // not mpm_solver (the healthy peer that reported it and called MPI_Abort).
  const auto s = tinyScene();
  const auto plan = coupler::composeLaunch(s, "tiny.yaml", "/b", "mpirun", 1, 1);
  const std::string text =
      "mpm_solver: error: coupler: Lagrangian momentum of steel sent, but no receipt from participant 'ice' "
      "within 3 s (coupling.timeout); it has stopped or hangs\n"
      "MPI_ABORT was invoked on rank 0 in communicator MPI_COMM_WORLD\n";
  const auto lines = coupler::explainFailure(plan, text);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].rfind("coupler: mpm_solver failed: coupler: Lagrangian momentum", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1], "coupler: world rank 0 is mpm_solver rank 0");
  EXPECT_EQ(lines[2], "coupler: ice_solver stopped answering: mpm_solver waited 3 s (coupling.timeout) for it; "
                      "the launch was ended");
}

TEST(CoupleRun, RejectsBadRankCounts) {
  const auto s = tinyScene();
  EXPECT_THROW(coupler::composeLaunch(s, "tiny.yaml", "/b", "mpirun", 0, 1), std::invalid_argument);
}

namespace {
core::Scene flapScene(const std::string& caseDir) {
  return core::parseScene(R"(
scene: flap
mesh: {dim: 2, lower: [-0.5, 0], upper: [0.5, 1.2], cells: [20, 24]}
time: {end: 0.5}
materials:
  - {name: flap, kind: solid, density: 3000, model: {type: neo_hookean, youngs_modulus: 4.0e6, poissons_ratio: 0.3}}
geometry:
  - {shape: {type: box, lo: [-0.05, 0], hi: [0.05, 1]}, material: flap}
coupling:
  schedule: explicit_serial
  fluid: openfoam
  ranks: {mpm: 2}
  interface: {solid: flap, patch: flap, case: ")" + caseDir + R"(", solver: pisoFoam}
)", "flap.yaml");
}
}  // namespace

TEST(CoupleRun, ComposesTheOpenFoamLaunchWithASerialFluid) {
  const auto s = flapScene("fluid");
  const auto plan = coupler::composeLaunch(s, "flap.yaml", "/b", "/x/mpirun", 2, 4, "/o/fluid");
  EXPECT_EQ(plan.commandLine(), "/x/mpirun -x WM_PROJECT_DIR -np 2 /b/mpm_solver/mpm_solver flap.yaml : -np 1 "
                                "pisoFoam -case /o/fluid");
  EXPECT_EQ(plan.describeWorldRank(2), "pisoFoam rank 0");
  ASSERT_EQ(plan.executables.size(), 1u);
}

TEST(CoupleRun, RestartResumesMpmSolverAndTheOpenFoamCaseCopy) {
  const auto s = flapScene("fluid");
  const auto plan = coupler::composeLaunch(s, "flap.yaml", "/b", "/x/mpirun", 2, 1, "/o/fluid", "output");
  EXPECT_EQ(plan.commandLine(), "/x/mpirun -x WM_PROJECT_DIR -np 2 /b/mpm_solver/mpm_solver --restart output flap.yaml "
                                ": -np 1 pisoFoam -case /o/fluid");
}

TEST(CoupleRun, AddsTheAdapterInsideTheFunctionsDictionary) {
  const std::string entry = coupler::adapterEntry("/b/lib.so", "/s/flap.yaml");
  EXPECT_NE(entry.find("type    mpmiceAdapter;"), std::string::npos);
  EXPECT_NE(entry.find("scene   \"/s/flap.yaml\";"), std::string::npos);
  // An existing functions dictionary keeps its objects; the adapter goes first inside it.
  const std::string withFunctions = "endTime 5;\nfunctions\n{\n    forces { type forces; }\n}\n";
  const std::string a = coupler::withFunctionObject(withFunctions, entry);
  EXPECT_EQ(a, "endTime 5;\nfunctions\n{\n" + entry + "\n    forces { type forces; }\n}\n");
  // Without one, a functions dictionary is appended; `functionsOther` is not a match.
  const std::string b = coupler::withFunctionObject("functionsOther 1;\n", entry);
  EXPECT_EQ(b, "functionsOther 1;\n\nfunctions\n{\n" + entry + "}\n");
}

TEST(CoupleRun, AMissingOpenFoamCaseNamesTheSceneKey) {
  const auto s = flapScene("no/such/case");
  std::ostringstream out;
  try {
    (void)coupler::prepareOpenFoamCase(s, "flap.yaml", "/b", out);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("flap.yaml:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("coupling.interface.case: 'no/such/case'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no system/controlDict"), std::string::npos) << msg;
  }
}

TEST(CoupleRun, StartsWithoutAShellAndPrintsTheLineShellQuoted) {
  const auto s = tinyScene();
  const std::string hostile = "x;touch${IFS}INJECTED;.yaml";
  const auto plan = coupler::composeLaunch(s, hostile, "/b", "/x/mpirun", 1, 1);
  // The argument reaches the program as one word; the printed line quotes it for copying.
  EXPECT_EQ(plan.argv[4], hostile);
  EXPECT_EQ(plan.commandLine(), "/x/mpirun -np 1 /b/mpm_solver/mpm_solver 'x;touch${IFS}INJECTED;.yaml' : -np 1 "
                                "/b/ice_solver/ice_solver 'x;touch${IFS}INJECTED;.yaml'");
  EXPECT_EQ(coupler::shellQuote("it's (a) & $HOME.yaml"), "'it'\\''s (a) & $HOME.yaml'");
  EXPECT_EQ(coupler::shellQuote(""), "''");
  EXPECT_EQ(coupler::shellQuote("dir/a-b_c.yaml"), "dir/a-b_c.yaml");  // plain words stay bare
}

TEST(CoupleRun, TheLaunchReceivesEveryArgumentAsOneWordAndIsTracked) {
  // A real process: every argument one word, output through the pipe, the exit status.
  coupler::Process p({"/bin/sh", "-c", "printf '%s|' \"$@\"; exit 3", "sh", "x;touch${IFS}INJECTED;.yaml", "a b",
                      "'q'"});
  std::string text;
  char buf[256];
  for (ssize_t n; (n = read(p.output(), buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
  EXPECT_EQ(text, "x;touch${IFS}INJECTED;.yaml|a b|'q'|");
  EXPECT_EQ(p.wait(), 3);
  EXPECT_THROW(coupler::Process({"/no/such/program"}), std::runtime_error);
}

namespace {
/// A minimal case folder (system/controlDict) under a fresh directory.
std::filesystem::path caseFolder(const std::string& name) {
  const auto root = std::filesystem::temp_directory_path() / ("mpmice_case_copy_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root / "fluid" / "system");
  std::ofstream(root / "fluid" / "system" / "controlDict") << "endTime 1;\n";
  return root;
}
}  // namespace

TEST(CoupleRun, TheCaseCopyNeverDeletesTheSourceCase) {
  const auto root = caseFolder("never_deletes");
  const auto src = root / "fluid";
  auto refused = [&](const std::filesystem::path& dst, const std::string& how) {
    try {
      coupler::copyCaseFresh(src, dst);
      ADD_FAILURE() << "expected a refusal for " << dst;
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("the OpenFOAM case copy"), std::string::npos) << msg;
      EXPECT_NE(msg.find(how + " the source case " + src.string() + "; refusing to overwrite it"), std::string::npos)
          << msg;
    }
    EXPECT_TRUE(std::filesystem::exists(src / "system" / "controlDict")) << "the source case was deleted";
  };
  refused(root / "." / "fluid", "is");    // output.directory: . with the case beside the scene
  refused(src / "out" / "fluid", "lies inside");
  refused(root, "contains");
  // A fresh copy elsewhere; a second run replaces its own earlier copy, not a foreign folder.
  coupler::copyCaseFresh(src, root / "output" / "fluid");
  EXPECT_TRUE(std::filesystem::exists(root / "output" / "fluid" / "system" / "controlDict"));
  coupler::copyCaseFresh(src, root / "output" / "fluid");
  std::filesystem::create_directories(root / "mine" / "fluid");
  std::ofstream(root / "mine" / "fluid" / "notes.txt") << "keep\n";
  EXPECT_THROW(coupler::copyCaseFresh(src, root / "mine" / "fluid"), std::invalid_argument);
  EXPECT_TRUE(std::filesystem::exists(root / "mine" / "fluid" / "notes.txt"));
  std::filesystem::remove_all(root);
}

TEST(CoupleRun, ATimeoutNamesWhatWasAwaitedOnce) {
  // Sending: the peer did not take the data ("no receipt of receipt of ..." was the old wording).
  EXPECT_EQ(coupler::timeoutMessage("ice", "solid state", 3, coupler::Waiting::ForReceipt),
            "coupler: solid state sent, but no receipt from participant 'ice' within 3 s (coupling.timeout); it has "
            "stopped or hangs");
  EXPECT_EQ(coupler::timeoutMessage("b", "solid state", 3, coupler::Waiting::ForData),
            "coupler: no solid state from participant 'b' within 3 s (coupling.timeout); it has stopped or hangs");
}

namespace {
/// A scratch folder with executable stand-ins at the given relative paths.
std::filesystem::path programTree(const std::string& name, const std::vector<std::string>& files) {
  const auto root = std::filesystem::temp_directory_path() / ("mpmice_locator_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(root);
  for (const auto& f : files) {
    std::filesystem::create_directories((root / f).parent_path());
    std::ofstream(root / f) << "#!/bin/sh\n";
    std::filesystem::permissions(root / f, std::filesystem::perms::owner_all);
  }
  return root;
}
}  // namespace

TEST(CoupleRun, FindsTheProgramsInAnInstalledBinDirectoryOrABuildDirectory) {
  // --bin-dir: DIR/<program> (installed) first, else DIR/<program>/<program> (a build directory).
  const auto installed = programTree("installed", {"bin/mpm_solver", "bin/ice_solver", "bin/coupler",
                                                   "libexec/mpmice/mpirun", "lib/libmpmiceFoamAdapter.so"});
  EXPECT_EQ(coupler::locateProgram("mpm_solver", (installed / "bin").string(), "/elsewhere"),
            (installed / "bin" / "mpm_solver").string());
  const auto build = programTree("build", {"mpm_solver/mpm_solver", "coupler/coupler", "adapters/openfoam/libmpmiceFoamAdapter.so"});
  EXPECT_EQ(coupler::locateProgram("mpm_solver", build.string(), "/elsewhere"), (build / "mpm_solver" / "mpm_solver").string());
  // Default: beside the coupler (installed), then the coupler's build tree.
  EXPECT_EQ(coupler::locateProgram("ice_solver", "", (installed / "bin").string()), (installed / "bin" / "ice_solver").string());
  EXPECT_EQ(coupler::locateProgram("mpm_solver", "", (build / "coupler").string()), (build / "mpm_solver" / "mpm_solver").string());
  // The adapter and the launch helper of each layout.
  EXPECT_EQ(coupler::locateAdapterLibrary("", (installed / "bin").string()),
            (installed / "lib" / "libmpmiceFoamAdapter.so").string());
  EXPECT_EQ(coupler::locateAdapterLibrary((installed / "bin").string(), "/elsewhere"),
            (installed / "lib" / "libmpmiceFoamAdapter.so").string());
  EXPECT_EQ(coupler::locateAdapterLibrary("", (build / "coupler").string()),
            (build / "adapters" / "openfoam" / "libmpmiceFoamAdapter.so").string());
  EXPECT_EQ(coupler::locateLaunchHelper((installed / "bin").string()), (installed / "libexec" / "mpmice" / "mpirun").string());
  std::filesystem::remove_all(installed);
  std::filesystem::remove_all(build);
}

TEST(CoupleRun, FindsTheProgramsOnPathWhenNoneIsBesideTheCoupler) {
  const auto tree = programTree("path", {"some/bin/ice_solver", "lonely/coupler"});
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  setenv("PATH", ("/nonexistent:" + (tree / "some" / "bin").string()).c_str(), 1);
  EXPECT_EQ(coupler::locateProgram("ice_solver", "", (tree / "lonely").string()), (tree / "some/bin/ice_solver").string());
  // Not found: the first place looked (beside the coupler), for the error message. A --bin-dir
  // is not combined with PATH: what the user named is where the programs must be.
  EXPECT_EQ(coupler::locateProgram("mpm_solver", "", (tree / "lonely").string()), (tree / "lonely" / "mpm_solver").string());
  EXPECT_EQ(coupler::locateProgram("ice_solver", "/b", (tree / "lonely").string()), "/b/ice_solver/ice_solver");
  setenv("PATH", saved.c_str(), 1);
  std::filesystem::remove_all(tree);
}

TEST(CoupleRun, ABoundedRunReportsItsStatusItsMemoryAndItsTimeLimit) {
  const auto log = std::filesystem::temp_directory_path() / ("bounded_" + std::to_string(::getpid()) + ".log");
  // A run that ends by itself: its status, its output in the log, its peak RSS.
  auto r = mpmice::coupler::runToFileWithin({"sh", "-c", "echo out; echo err >&2; exit 7"}, log.string(), 30);
  EXPECT_FALSE(r.timedOut);
  EXPECT_EQ(r.status, 7);
  EXPECT_GT(r.peakRssKb, 0);
  EXPECT_GT(r.wallSeconds, 0);
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "out\nerr\n");
  // A run past its limit: its group gets SIGTERM (status 128 + 15), and the child it started too.
  r = mpmice::coupler::runToFileWithin({"sh", "-c", "sleep 60 & wait"}, log.string(), 0.2);
  EXPECT_TRUE(r.timedOut);
  EXPECT_EQ(r.status, 128 + 15);
  // A limit that is not > 0 is refused.
  EXPECT_THROW((void)mpmice::coupler::runToFileWithin({"true"}, log.string(), 0), std::invalid_argument);
  std::filesystem::remove(log);
}

namespace {
/// A run's output directory as a surface-coupled run with checkpoints leaves it: the case copy
/// (marker, controlDict, time directories `times`) and the solid's checkpoint of step 5 at t.
core::Scene resumableRun(const std::filesystem::path& root, const std::vector<std::string>& times, double t) {
  namespace fs = std::filesystem;
  fs::remove_all(root);
  fs::create_directories(root / "out" / "fluid" / "system");
  std::ofstream(root / "out" / "fluid" / ".mpmice_case_copy") << "copy\n";
  std::ofstream(root / "out" / "fluid" / "system" / "controlDict")
      << "startFrom       latestTime;\nstartTime       0;\nendTime         0.5;\nwritePrecision  8;\n";
  for (const auto& name : times) fs::create_directories(root / "out" / "fluid" / name);
  core::H5File::create((root / "out" / "flap_checkpoint_000005.h5").string()).root().writeAttribute("time", std::vector<double>{t});
  return core::parseScene(R"(
scene: flap
mesh: {dim: 2, lower: [-0.5, 0], upper: [0.5, 1.2], cells: [20, 24]}
time: {end: 0.8}
materials:
  - {name: flap, kind: solid, density: 3000, model: {type: neo_hookean, youngs_modulus: 4.0e6, poissons_ratio: 0.3}}
geometry:
  - {shape: {type: box, lo: [-0.05, 0], hi: [0.05, 1]}, material: flap}
coupling:
  schedule: explicit_serial
  fluid: openfoam
  interface: {solid: flap, patch: flap, case: fluid, solver: pimpleFoam}
output: {directory: ")" + (root / "out").string() + R"(", checkpoint_interval: 0.05}
)", (root / "flap.yaml").string());
}
}  // namespace

TEST(CoupleRun, ARestartStartsTheCaseCopyFromTheCheckpointsTimeDirectory) {
  const auto root = std::filesystem::temp_directory_path() / ("mpmice_of_resume_" + std::to_string(getpid()));
  const auto s = resumableRun(root, {"0", "0.05", "0.1", "0.15"}, 0.1);
  std::ostringstream out;
  const std::string copy = coupler::resumeOpenFoamCase(s, (root / "flap.yaml").string(), (root / "out").string(), out);
  EXPECT_EQ(copy, (root / "out" / "fluid").string());
  const std::string cd = [&] {
    std::ifstream in(root / "out" / "fluid" / "system" / "controlDict");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  EXPECT_NE(cd.find("startFrom  startTime;"), std::string::npos) << cd;
  EXPECT_NE(cd.find("startTime  0.10000000000000001;"), std::string::npos) << cd;  // the checkpoint's, to 17 digits
  EXPECT_NE(cd.find("endTime  0.80000000000000004;"), std::string::npos) << cd;  // the scene's, to 17 digits
  EXPECT_NE(cd.find("writePrecision  17;"), std::string::npos) << cd;
  EXPECT_NE(out.str().find("resumes from " + (root / "out" / "fluid" / "0.1").string()), std::string::npos) << out.str();
  EXPECT_TRUE(std::filesystem::exists(root / "out" / "fluid" / "0.15")) << "a later time directory was deleted";
  std::filesystem::remove_all(root);
}

TEST(CoupleRun, ARestartWithoutTheMatchingTimeDirectoryNamesBoth) {
  const auto root = std::filesystem::temp_directory_path() / ("mpmice_of_noresume_" + std::to_string(getpid()));
  const auto s = resumableRun(root, {"0", "0.05", "0.15"}, 0.1);
  std::ostringstream out;
  try {
    (void)coupler::resumeOpenFoamCase(s, (root / "flap.yaml").string(), (root / "out").string(), out);
    ADD_FAILURE() << "a checkpoint without its time directory must be refused";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("the checkpoint " + (root / "out" / "flap_checkpoint_000005.h5").string() + " is at t = 0.1"),
              std::string::npos) << msg;
    EXPECT_NE(msg.find("OpenFOAM case copy " + (root / "out" / "fluid").string() + " has no time directory"),
              std::string::npos) << msg;
    EXPECT_NE(msg.find("(it has: "), std::string::npos) << msg;
  }
  std::filesystem::remove_all(root / "out" / "fluid");
  EXPECT_THROW((void)coupler::resumeOpenFoamCase(s, (root / "flap.yaml").string(), (root / "out").string(), out),
               std::invalid_argument);  // no case copy at all
  std::filesystem::remove_all(root);
}
