#include "coupler/cli/run_command.h"
#include "coupler/cli/command_line.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <poll.h>
#include <regex>
#include <algorithm>
#include <set>
#include <sstream>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "coupler/cli/openfoam_case.h"
#include "coupler/cli/process.h"
#include "core/io/run_lock.h"
#include "core/scene/did_you_mean.h"
#include "core/version.h"

#ifndef MPMICE_MPIRUN_PATH
#define MPMICE_MPIRUN_PATH "mpirun"
#endif

namespace mpmice::coupler {

namespace fs = std::filesystem;

std::string LaunchPlan::commandLine() const { return shellLine(argv); }

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
    plan.participants = {"mpm", "openfoam"};
    plan.ranks = {mpmRanks, 1};
    plan.executables = {mpm};
    plan.argv = {mpirun, "-x", "WM_PROJECT_DIR", "-np", std::to_string(mpmRanks), mpm, sceneFile,
                 ":", "-np", "1", solver, "-case", fluidCase};
    return plan;
  }
  // A scene of one kind of material needs one program (the other would have nothing to solve).
  if (scene.fluids().empty()) {
    plan.programs = {"mpm_solver"};
    plan.participants = {"mpm"};
    plan.ranks = {mpmRanks};
  } else if (scene.solids().empty()) {
    plan.programs = {"ice_solver"};
    plan.participants = {"ice"};
    plan.ranks = {iceRanks};
  } else {
    plan.programs = {"mpm_solver", "ice_solver"};
    plan.participants = {"mpm", "ice"};
    plan.ranks = {mpmRanks, iceRanks};
  }
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
  std::string stopped;  // the closing line when a side timed out waiting for its peer
  // The side that failed says so itself ("ice_solver: error: ..."): name it first, with its
  // message (mpirun's own report of which rank aborted is racy and may be missing).
  static const std::regex timedOut(R"(from participant '([^']+)' within ([^ ]+) s \(coupling\.timeout\); it has stopped or hangs)");
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    for (std::size_t p = 0; p < plan.programs.size(); ++p) {
      const std::string& program = plan.programs[p];
      const std::string tag = program + ": error: ";
      if (const auto at = line.find(tag); at != std::string::npos) {  // another program's output may precede it
        const std::string message = line.substr(at + tag.size());
        const std::string failed = "coupler: " + program + " failed: " + message;
        if (std::find(lines.begin(), lines.end(), failed) == lines.end()) lines.push_back(failed);
        std::smatch m;
        if (!stopped.empty() || !std::regex_search(message, m, timedOut)) continue;
        // The healthy side timed out: the participant it waited for is the one that stopped.
        const auto peer = std::find(plan.participants.begin(), plan.participants.end(), m[1].str());
        const std::string who = peer == plan.participants.end()
                                    ? "participant '" + m[1].str() + "'"
                                    : plan.programs[static_cast<std::size_t>(peer - plan.participants.begin())];
        stopped = "coupler: " + who + " stopped answering: " + program + " waited " + m[2].str() +
                  " s (coupling.timeout) for it; the launch was ended";
      }
    }
  for (int r : ranks) {
    const std::string who = plan.describeWorldRank(r);
    if (!who.empty()) lines.push_back("coupler: world rank " + std::to_string(r) + " is " + who);
  }
  if (!stopped.empty()) lines.push_back(stopped);  // the closing line names who stopped answering
  return lines;
}

namespace {

std::string ownBinDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return ".";
  return exe.parent_path().parent_path().string();  // <bin>/coupler/coupler -> <bin>
}

volatile std::sig_atomic_t g_stopSignal = 0;

std::string signalName(int sig) {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    default: return "signal " + std::to_string(sig);
  }
}

extern "C" void recordStopSignal(int sig) { g_stopSignal = sig; }

/// SIGINT and SIGTERM recorded (not fatal) while it lives; the previous handlers restored after.
class StopSignals {
 public:
  StopSignals() {
    g_stopSignal = 0;
    struct sigaction sa {};
    sa.sa_handler = recordStopSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;  // no SA_RESTART: poll() returns at once
    sigaction(SIGINT, &sa, &oldInt_);
    sigaction(SIGTERM, &sa, &oldTerm_);
  }
  ~StopSignals() {
    sigaction(SIGINT, &oldInt_, nullptr);
    sigaction(SIGTERM, &oldTerm_, nullptr);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

 private:
  struct sigaction oldInt_ {}, oldTerm_ {};
};

/// Runs the launch without a shell, streaming its output through `out`. SIGINT/SIGTERM to the
/// coupler go to the launch's process group; the coupler waits for it (SIGKILL after 10 s).
int runLaunch(const LaunchPlan& plan, std::ostream& out, std::ostream& err) {
  const StopSignals signals;
  Process launch(plan.argv);
  std::string all;
  char buf[4096];
  int forwarded = 0;
  auto forwardedAt = std::chrono::steady_clock::now();
  bool killed = false;
  std::optional<std::chrono::steady_clock::time_point> endedAt;
  for (;;) {
    if (g_stopSignal != 0 && forwarded == 0) {
      forwarded = g_stopSignal;
      forwardedAt = std::chrono::steady_clock::now();
      err << "coupler: " << signalName(forwarded) << " received: stopping the launch\n" << std::flush;
      launch.signalGroup(forwarded);
    }
    if (forwarded != 0 && !killed && std::chrono::steady_clock::now() - forwardedAt > std::chrono::seconds(10)) {
      err << "coupler: the launch did not end within 10 s of " << signalName(forwarded) << ": killing it\n";
      launch.signalGroup(SIGKILL);
      killed = true;
    }
    // After mpirun has ended, what it left in the pipe is read for up to 1 s (a process that
    // kept the pipe open is killed with the group by wait()).
    if (!endedAt && launch.ended()) endedAt = std::chrono::steady_clock::now();
    if (endedAt && std::chrono::steady_clock::now() - *endedAt > std::chrono::seconds(1)) break;
    pollfd pfd{launch.output(), POLLIN, 0};
    const int ready = poll(&pfd, 1, 200);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = read(launch.output(), buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of output: every writer has closed the pipe
    out.write(buf, n);
    out << std::flush;
    all.append(buf, static_cast<std::size_t>(n));
    if (all.size() > (1u << 20)) all.erase(0, all.size() - (1u << 19));  // keep the tail
  }
  const int code = launch.wait();
  if (forwarded != 0) {
    err << "coupler: stopped by " << signalName(forwarded) << "; the launch ended with status " << code << "\n";
    return 128 + forwarded;
  }
  if (code != 0) {
    err << "coupler: the launch ended with status " << code << "\n";
    for (const auto& line : explainFailure(plan, all)) err << line << "\n";
    return code;
  }
  return 0;
}

}  // namespace

namespace {

struct RunOptions {
  std::string sceneFile, binDir;
  int mpmRanks = 0, iceRanks = 0;  // 0: the scene's coupling.ranks
  bool dryRun = false;
};

/// The `coupler run` command line (CLI11), bound to `o`.
void describeRun(CLI::App& app, RunOptions& o) {
  app.description(
      "Composes the MPMD launch of mpm_solver and ice_solver on the scene (mpm_solver and the scene's "
      "OpenFOAM solver for coupling.fluid: openfoam; one program when the scene has one kind of "
      "material), prints it, runs it without a shell and names the participant behind any failure. "
      "SIGINT/SIGTERM are forwarded to the launch (exit 128 + signal); the output directory is locked "
      "for the run.");
  app.get_formatter()->label("Usage", "usage");
  app.set_help_flag("-h,--help", "print this help and exit");
  app.set_version_flag("-V,--version", core::versionLine("coupler"), "print the version and exit");
  const auto ranks = CLI::Validator(
      [](std::string& v) -> std::string {
        try {
          std::size_t used = 0;
          const int n = std::stoi(v, &used);
          if (used == v.size() && n >= 1) return {};
        } catch (const std::exception&) {
        }
        return "expects a whole number >= 1, got '" + v + "'";
      },
      "", "");
  app.add_option("--mpm-ranks", o.mpmRanks, "MPM ranks (default: the scene's coupling.ranks.mpm)")
      ->type_name("N")->check(ranks);
  app.add_option("--ice-ranks", o.iceRanks, "ICE ranks (default: the scene's coupling.ranks.ice)")
      ->type_name("N")->check(ranks);
  app.add_option("--bin-dir", o.binDir,
                 "the build directory holding mpm_solver/mpm_solver and ice_solver/ice_solver "
                 "(default: the one of this coupler)")
      ->type_name("DIR");
  app.add_flag("--dry-run", o.dryRun, "print the launch line without running it");
  app.add_option("scene.yaml", o.sceneFile, "the scene file")->required();
  app.footer("Sample runs:\n"
             "  coupler run configs/pressurized_cylinder.yaml\n"
             "  coupler run --mpm-ranks 2 --ice-ranks 2 --dry-run configs/pressurized_cylinder.yaml\n"
             "  coupler run --bin-dir build configs/flap_openfoam.yaml\n");
}

}  // namespace

std::string runUsage() {
  RunOptions o;
  CLI::App app("", "coupler run");
  describeRun(app, o);
  return app.help();
}

int runRun(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  RunOptions o;
  o.binDir = ownBinDir();
  {
    CLI::App app("", "coupler run");
    describeRun(app, o);
    if (const auto done = parseSubcommand(app, args, "coupler run",
                                          "coupler run [--mpm-ranks N] [--ice-ranks N] [--bin-dir DIR] [--dry-run] <scene.yaml>",
                                          out, err))
      return *done;
  }
  const std::string& sceneFile = o.sceneFile;
  const std::string& binDir = o.binDir;
  int mpmRanks = o.mpmRanks, iceRanks = o.iceRanks;
  const bool dryRun = o.dryRun;
  try {
    const core::Scene scene = core::loadScene(sceneFile);
    if (mpmRanks == 0) mpmRanks = scene.coupling.mpm_ranks;
    if (iceRanks == 0) iceRanks = scene.coupling.ice_ranks;
    // The output-directory lock, before anything is written (core/io/run_lock.h); the launch's
    // programs accept it as their coupler's.
    std::unique_ptr<core::RunLock> lock;
    if (!dryRun) {
      try {
        lock = core::lockOutputDirectory(core::Comm(), scene, "coupler", &err);
      } catch (const std::exception& e) {
        throw std::runtime_error(std::string("coupler run: ") + e.what());
      }
    }
    std::string fluidCase;
    if (scene.coupling.fluid == core::FluidSolver::OpenFoam && !dryRun) fluidCase = prepareOpenFoamCase(scene, sceneFile, binDir, out);
    const LaunchPlan plan = composeLaunch(scene, sceneFile, binDir, MPMICE_MPIRUN_PATH, mpmRanks, iceRanks, fluidCase);
    for (const auto& exe : plan.executables)
      if (!fs::exists(exe))
        throw std::invalid_argument("coupler run: " + exe + " does not exist; build it, or point --bin-dir at the build directory");
    if (plan.programs.size() == 1)
      out << "coupler: scene '" << scene.name << "' has " << (scene.fluids().empty() ? "no fluid" : "no solid")
          << ": " << plan.programs[0] << " alone on " << plan.ranks[0] << (plan.ranks[0] == 1 ? " rank" : " ranks")
          << "\n";
    else
      out << "coupler: scene '" << scene.name << "', schedule " << core::name(scene.coupling.schedule) << ", "
          << mpmRanks << " MPM + "
          << (scene.coupling.fluid == core::FluidSolver::OpenFoam
                  ? "1 " + scene.coupling.interface.openfoam_solver + " rank"
                  : std::to_string(iceRanks) + " ICE ranks")
          << "\n";
    out
        << "coupler: " << plan.commandLine() << "\n"
        << std::flush;
    if (dryRun) return 0;
    // Debian's OpenFOAM finds its etc/ through WM_PROJECT_DIR (exported to the launch by -x).
    if (scene.coupling.fluid == core::FluidSolver::OpenFoam) setenv("WM_PROJECT_DIR", "/usr/share/openfoam", 0);

    return runLaunch(plan, out, err);
  } catch (const core::SceneError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << e.what() << "\n";
    return 2;
  }
}

}  // namespace mpmice::coupler
