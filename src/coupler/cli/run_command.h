#pragma once
/// @brief `coupler run [options] <scene.yaml>`: composes the MPMD launch of the two solvers,
/// prints it, runs it, and names the participant behind any failure.
///
///   coupler run configs/pressurized_cylinder.yaml
///   -> scripts/mpirun -np 1 <build>/mpm_solver/mpm_solver s.yaml : -np 1 <build>/ice_solver/ice_solver s.yaml
///      (installed: <prefix>/libexec/mpmice/mpirun -np 1 <prefix>/bin/mpm_solver s.yaml : ...)
///   coupler run configs/flap_openfoam.yaml            (coupling.fluid: openfoam)
///   -> scripts/mpirun -x WM_PROJECT_DIR -np 1 <bin>/mpm_solver/mpm_solver s.yaml
///        : -np 1 pimpleFoam -case <output>/<case>   (the case prepared by cli/openfoam_case.h)
///
/// Rank counts come from the scene's coupling.ranks (mpm, ice) unless --mpm-ranks / --ice-ranks
/// override them. --dry-run prints the line without running it. The launch's output streams
/// through; when it ends non-zero, the world ranks named in mpirun's messages are translated
/// into participants ("world rank 1 is ice_solver rank 0").
///
/// The launch starts without a shell (cli/process.h: argv through posix_spawn, its own process
/// group); the printed line is shell-quoted. SIGINT/SIGTERM to the coupler are forwarded to the
/// launch's group, the coupler waits for it to end (SIGKILL after 10 s) and exits 128 + signal,
/// "coupler: stopped by SIGTERM". The output directory is locked for the run (core/io/run_lock.h).
#include <ostream>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace mpmice::coupler {

struct LaunchPlan {
  std::vector<std::string> argv;        // the full command line
  std::vector<std::string> programs;    // program name per participant, in launch order
  std::vector<std::string> participants;  // participant name per program ("mpm", "ice", "openfoam")
  std::vector<int> ranks;               // ranks per participant
  std::vector<std::string> executables; // per participant (checked before the launch)
  [[nodiscard]] std::string commandLine() const;
  /// "ice_solver rank 0" for a world rank; empty when out of range.
  [[nodiscard]] std::string describeWorldRank(int worldRank) const;
};

/// The launch for `sceneFile` with the programs found from binDir (--bin-dir; empty: beside this
/// coupler, its build tree, then PATH; cli/program_locator.h).
/// coupling.fluid openfoam: mpm_solver and the scene's OpenFOAM solver (serial) in `fluidCase`.
LaunchPlan composeLaunch(const core::Scene& scene, const std::string& sceneFile, const std::string& binDir,
                         const std::string& mpirun, int mpmRanks, int iceRanks, const std::string& fluidCase = "",
                         const std::string& restart = "");

/// The usage text of `coupler run` (`coupler run --help`).
std::string runUsage();

/// Runs `coupler run` on args (after "run"); returns the exit status.
int runRun(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// Explains the world ranks that mpirun's failure text mentions (one line each). When the side
/// that failed timed out waiting for its peer ("... from participant 'ice' within 3 s ..."), the
/// last line names the peer's program as the one that stopped answering.
std::vector<std::string> explainFailure(const LaunchPlan& plan, const std::string& launchOutput);

}  // namespace mpmice::coupler
