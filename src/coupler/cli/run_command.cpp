#include "coupler/cli/run_command.h"
#include "coupler/cli/command_line.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <poll.h>
#include <regex>
#include <algorithm>
#include <set>
#include <sstream>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "coupler/cli/launch_output.h"
#include "coupler/cli/openfoam_case.h"
#include "coupler/cli/process.h"
#include "coupler/cli/program_locator.h"
#include "coupler/cli/stop_signals.h"
#include "core/io/run_lock.h"
#include "core/scene/did_you_mean.h"
#include "core/version.h"

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
                         const std::string& mpirun, int mpmRanks, int iceRanks, const std::string& fluidCase,
                         const std::string& restart) {
  if (mpmRanks < 1 || iceRanks < 1) throw std::invalid_argument("coupler run: rank counts must be >= 1");
  LaunchPlan plan;
  if (scene.coupling.fluid == core::FluidSolver::OpenFoam) {
    // Serial OpenFOAM: v1912's Pstream would take MPI_COMM_WORLD (adapters/openfoam/README.md).
    const std::string solver = scene.coupling.interface.openfoam_solver;
    const std::string mpm = locateProgram("mpm_solver", binDir, ownDirectory());
    plan.programs = {"mpm_solver", solver};
    plan.participants = {"mpm", "openfoam"};
    plan.ranks = {mpmRanks, 1};
    plan.executables = {mpm};
    // A restart: mpm_solver resumes its checkpoint; the solver its case copy's time directory of
    // the same time (resumeOpenFoamCase set the copy's controlDict to start there).
    plan.argv = {mpirun, "-x", "WM_PROJECT_DIR", "-np", std::to_string(mpmRanks), mpm};
    if (!restart.empty()) plan.argv.insert(plan.argv.end(), {"--restart", restart});
    plan.argv.insert(plan.argv.end(), {sceneFile, ":", "-np", "1", solver, "-case", fluidCase});
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
    const std::string exe = locateProgram(plan.programs[p], binDir, ownDirectory());
    plan.executables.push_back(exe);
    plan.argv.insert(plan.argv.end(), {"-np", std::to_string(plan.ranks[p]), exe});
    if (!restart.empty()) plan.argv.insert(plan.argv.end(), {"--restart", restart});
    plan.argv.push_back(sceneFile);
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

/// Runs the launch without a shell, its output through LaunchOutput (cli/launch_output.h) to `out`. SIGINT/SIGTERM to the
/// coupler go to the launch's process group; the coupler waits for it (SIGKILL after 10 s).
int runLaunch(const LaunchPlan& plan, std::ostream& out, std::ostream& err, std::unique_ptr<core::LogFile> fluidLog) {
  const StopSignals signals;
  Process launch(plan.argv);
  const int fluidProgram = fluidLog ? static_cast<int>(plan.programs.size()) - 1 : -1;
  const bool inPlace = &out == &std::cout && isatty(STDOUT_FILENO) == 1;  // one progress line that moves
  LaunchOutput output(plan, out, std::move(fluidLog), fluidProgram, inPlace);
  char buf[4096];
  int forwarded = 0;
  auto forwardedAt = std::chrono::steady_clock::now();
  bool killed = false;
  std::optional<std::chrono::steady_clock::time_point> endedAt;
  for (;;) {
    if (StopSignals::received() != 0 && forwarded == 0) {
      forwarded = StopSignals::received();
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
    output.feed(std::string_view(buf, static_cast<std::size_t>(n)));
  }
  const int code = launch.wait();
  output.finish(code == 0 && forwarded == 0);
  const std::string& all = output.text();
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
  std::string sceneFile, binDir, restart;
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
      "for the run. The terminal shows the progress and one labelled summary per side (steps, compute and "
      "wait time, coupling iterations); each program keeps its output in <output>/log.<program>, the "
      "OpenFOAM solver's in <output>/log.<solver>.");
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
                 "where the programs are: an installed bin directory (DIR/mpm_solver, DIR/ice_solver) or a "
                 "build directory (DIR/mpm_solver/mpm_solver, DIR/ice_solver/ice_solver); the OpenFOAM adapter "
                 "is looked for in DIR/../lib or DIR/adapters/openfoam (default: beside this coupler, then its "
                 "build tree, then PATH)")
      ->type_name("DIR");
  app.add_flag("--dry-run", o.dryRun, "print the launch line without running it");
  app.add_option("--restart", o.restart,
                 "resume from a checkpoint (output.checkpoint_interval): an output directory (the latest "
                 "checkpoint there) or one program's checkpoint file; passed to both programs, each "
                 "resumes from its own file of that step (coupling.fluid: openfoam: mpm_solver from its "
                 "checkpoint, the OpenFOAM solver from the time directory of the same time in the run's "
                 "case copy)")
      ->type_name("PATH");
  app.add_option("scene.yaml", o.sceneFile, "the scene file")->required();
  app.footer("Sample runs:\n"
             "  coupler run configs/pressurized_cylinder.yaml\n"
             "  coupler run --mpm-ranks 2 --ice-ranks 2 --dry-run configs/pressurized_cylinder.yaml\n"
             "  coupler run --bin-dir build configs/flap_openfoam.yaml\n"
             "  coupler run --bin-dir /opt/mpmice/bin configs/pressurized_cylinder.yaml\n"
             "  coupler run --restart output configs/pressurized_cylinder.yaml\n");
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
  {
    CLI::App app("", "coupler run");
    describeRun(app, o);
    if (const auto done = parseSubcommand(app, args, "coupler run",
                                          "coupler run [--mpm-ranks N] [--ice-ranks N] [--bin-dir DIR] [--dry-run] [--restart PATH] <scene.yaml>",
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
    if (scene.coupling.fluid == core::FluidSolver::OpenFoam && !dryRun)
      fluidCase = o.restart.empty() ? prepareOpenFoamCase(scene, sceneFile, binDir, out)
                                    : resumeOpenFoamCase(scene, sceneFile, o.restart, out);
    const LaunchPlan plan =
        composeLaunch(scene, sceneFile, binDir, locateLaunchHelper(ownDirectory()), mpmRanks, iceRanks, fluidCase, o.restart);
    for (std::size_t p = 0; p < plan.executables.size(); ++p)
      if (!fs::exists(plan.executables[p]))
        throw std::invalid_argument(
            "coupler run: " + plan.programs[p] + " not found (" +
            (binDir.empty() ? "not beside this coupler in " + ownDirectory() + ", not in its build tree, not on PATH"
                            : "neither " + shellLine(programCandidates(plan.programs[p], binDir, ownDirectory())) +
                                  " exists") +
            "); build or install it, or point --bin-dir at the directory that holds it");
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
    // --tag-output: each piece of output names its world rank, so the coupler sorts it by program
    // (cli/launch_output.h: the OpenFOAM solver's lines to its log, one labelled summary per side).
    LaunchPlan tagged = plan;
    tagged.argv.insert(tagged.argv.begin() + 1, "--tag-output");
    out << "coupler: " << tagged.commandLine() << "\n" << std::flush;
    if (dryRun) return 0;
    // Debian's OpenFOAM finds its etc/ through WM_PROJECT_DIR (exported to the launch by -x).
    if (scene.coupling.fluid == core::FluidSolver::OpenFoam) setenv("WM_PROJECT_DIR", "/usr/share/openfoam", 0);

    std::unique_ptr<core::LogFile> fluidLog;  // <output>/log.<solver>: the OpenFOAM solver's output
    if (scene.coupling.fluid == core::FluidSolver::OpenFoam)
      fluidLog = std::make_unique<core::LogFile>(core::logFilePath(scene, plan.programs.back()), plan.programs.back(), scene,
                                                 "coupler");
    return runLaunch(tagged, out, err, std::move(fluidLog));
  } catch (const core::SceneError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << e.what() << "\n";
    return 2;
  }
}

}  // namespace mpmice::coupler
