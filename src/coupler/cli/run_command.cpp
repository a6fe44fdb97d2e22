#include "coupler/cli/run_command.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <sys/wait.h>

#include "coupler/cli/openfoam_case.h"
#include "core/scene/did_you_mean.h"

#ifndef MPMICE_MPIRUN_PATH
#define MPMICE_MPIRUN_PATH "mpirun"
#endif

namespace mpmice::coupler {

namespace fs = std::filesystem;

std::string LaunchPlan::commandLine() const {
  std::string s;
  for (const auto& a : argv) {
    if (!s.empty()) s += ' ';
    const bool quote = a.find_first_of(" \t'\"") != std::string::npos;
    s += quote ? "'" + a + "'" : a;
  }
  return s;
}

std::string LaunchPlan::describeWorldRank(int worldRank) const {
  int first = 0;
  for (std::size_t p = 0; p < programs.size(); ++p) {
    if (worldRank >= first && worldRank < first + ranks[p])
      return programs[p] + " rank " + std::to_string(worldRank - first);
    first += ranks[p];
  }
  return {};
}

LaunchPlan composeLaunch(const core::Scene& scene, const std::string& sceneFile, const std::string& binDir,
                         const std::string& mpirun, int mpmRanks, int iceRanks, const std::string& fluidCase) {
  if (mpmRanks < 1 || iceRanks < 1) throw std::invalid_argument("coupler run: rank counts must be >= 1");
  LaunchPlan plan;
  if (scene.coupling.fluid == core::FluidSolver::OpenFoam) {
    // Serial OpenFOAM: v1912's Pstream would take MPI_COMM_WORLD (adapters/openfoam/README.md).
    const std::string solver = scene.coupling.interface.openfoam_solver;
    const std::string mpm = (fs::path(binDir) / "mpm_solver" / "mpm_solver").string();
    plan.programs = {"mpm_solver", solver};
    plan.ranks = {mpmRanks, 1};
    plan.executables = {mpm};
    plan.argv = {mpirun, "-x", "WM_PROJECT_DIR", "-np", std::to_string(mpmRanks), mpm, sceneFile,
                 ":", "-np", "1", solver, "-case", fluidCase};
    return plan;
  }
  plan.programs = {"mpm_solver", "ice_solver"};
  plan.ranks = {mpmRanks, iceRanks};
  plan.argv = {mpirun};
  for (std::size_t p = 0; p < plan.programs.size(); ++p) {
    if (p) plan.argv.emplace_back(":");
    const fs::path exe = fs::path(binDir) / plan.programs[p] / plan.programs[p];
    plan.executables.push_back(exe.string());
    plan.argv.insert(plan.argv.end(), {"-np", std::to_string(plan.ranks[p]), exe.string(), sceneFile});
  }
  return plan;
}

std::vector<std::string> explainFailure(const LaunchPlan& plan, const std::string& text) {
  // Open MPI names failed processes as "rank N" or "[[jobid,vpid],N]" ("Process name").
  std::set<int> ranks;
  const std::regex patterns[] = {std::regex(R"(\brank (\d+)\b)"), std::regex(R"(\[\[\d+,\d+\],(\d+)\])")};
  for (const auto& re : patterns)
    for (std::sregex_iterator it(text.begin(), text.end(), re), end; it != end; ++it)
      ranks.insert(std::stoi((*it)[1]));
  std::vector<std::string> lines;
  for (int r : ranks) {
    const std::string who = plan.describeWorldRank(r);
    if (!who.empty()) lines.push_back("coupler: world rank " + std::to_string(r) + " is " + who);
  }
  return lines;
}

namespace {

std::string ownBinDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return ".";
  return exe.parent_path().parent_path().string();  // <bin>/coupler/coupler -> <bin>
}

int parseRanks(const std::string& opt, const std::string& v) {
  try {
    std::size_t used = 0;
    const int n = std::stoi(v, &used);
    if (used == v.size() && n >= 1) return n;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument("coupler run: " + opt + " expects a whole number >= 1, got '" + v + "'");
}

}  // namespace

int runRun(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::string sceneFile, binDir = ownBinDir();
  int mpmRanks = 0, iceRanks = 0;
  bool dryRun = false;
  try {
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= args.size()) throw std::invalid_argument("coupler run: " + a + " needs a value");
        return args[++i];
      };
      if (a == "--mpm-ranks") mpmRanks = parseRanks(a, value());
      else if (a == "--ice-ranks") iceRanks = parseRanks(a, value());
      else if (a == "--bin-dir") binDir = value();
      else if (a == "--dry-run") dryRun = true;
      else if (!a.empty() && a[0] == '-')
        throw std::invalid_argument("coupler run: unknown option '" + a + "'" +
                                    core::scene_detail::didYouMean(a, {"--mpm-ranks", "--ice-ranks", "--bin-dir", "--dry-run"}));
      else if (sceneFile.empty()) sceneFile = a;
      else throw std::invalid_argument("coupler run: one scene file expected, got '" + sceneFile + "' and '" + a + "'");
    }
    if (sceneFile.empty()) throw std::invalid_argument("coupler run: no scene file given");
    const core::Scene scene = core::loadScene(sceneFile);
    if (mpmRanks == 0) mpmRanks = scene.coupling.mpm_ranks;
    if (iceRanks == 0) iceRanks = scene.coupling.ice_ranks;
    std::string fluidCase;
    if (scene.coupling.fluid == core::FluidSolver::OpenFoam && !dryRun) fluidCase = prepareOpenFoamCase(scene, sceneFile, binDir, out);
    const LaunchPlan plan = composeLaunch(scene, sceneFile, binDir, MPMICE_MPIRUN_PATH, mpmRanks, iceRanks, fluidCase);
    for (const auto& exe : plan.executables)
      if (!fs::exists(exe))
        throw std::invalid_argument("coupler run: " + exe + " does not exist; build it, or point --bin-dir at the build directory");
    out << "coupler: scene '" << scene.name << "', schedule " << core::name(scene.coupling.schedule) << ", " << mpmRanks
        << " MPM + " << (scene.coupling.fluid == core::FluidSolver::OpenFoam ? "1 " + scene.coupling.interface.openfoam_solver + " rank"
                                                              : std::to_string(iceRanks) + " ICE ranks")
        << "\n"
        << "coupler: " << plan.commandLine() << "\n"
        << std::flush;
    if (dryRun) return 0;
    // Debian's OpenFOAM finds its etc/ through WM_PROJECT_DIR (exported to the launch by -x).
    if (scene.coupling.fluid == core::FluidSolver::OpenFoam) setenv("WM_PROJECT_DIR", "/usr/share/openfoam", 0);

    FILE* pipe = popen((plan.commandLine() + " 2>&1").c_str(), "r");
    if (!pipe) throw std::runtime_error("coupler run: could not start " + plan.argv[0]);
    std::string all;
    char buf[4096];
    while (fgets(buf, sizeof(buf), pipe)) {
      out << buf << std::flush;
      all += buf;
      if (all.size() > (1u << 20)) all.erase(0, all.size() - (1u << 19));  // keep the tail
    }
    const int status = pclose(pipe);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    if (code != 0) {
      err << "coupler: the launch ended with status " << code << "\n";
      for (const auto& line : explainFailure(plan, all)) err << line << "\n";
      return code;
    }
    return 0;
  } catch (const core::SceneError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << e.what() << "\n";
    return 2;
  }
}

}  // namespace mpmice::coupler
