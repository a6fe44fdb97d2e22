// mpm_solver: runs a solid-only scene with the explicit Material Point Method, or the solid side
// of an MPM-ICE run when started in one MPMD launch with ice_solver.
//
// Sample runs:  mpm_solver configs/mpm_vibrating_bar.yaml
//               scripts/mpirun -np 4 mpm_solver configs/mpm_colliding_disks.yaml
//               scripts/mpirun -np 1 mpm_solver s.yaml : -np 1 ice_solver s.yaml   (coupled)
//               mpm_solver --help                  (or --version)
// 1. Read and validate the scene (errors name file, line and key; exit 1); join the launch
//    (src/coupler/launch/participant.h): with a peer, run the coupled solid side and stop there
//    (MPM-ICE: src/couplings/volume/solid; a surface coupling with OpenFOAM: src/couplings/surface/solid).
// 2. Alone: run the scene (src/mpm/solver/standalone_run.h: progress lines, HDF5/XDMF output,
//    the energies CSV, probes).
#include <algorithm>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "coupler/launch/output_lock.h"
#include "coupler/launch/participant.h"
#include "couplings/volume/solid/solid_participant.h"
#include "couplings/surface/solid/file_load.h"
#include "couplings/surface/solid/surface_solid_participant.h"
#include "core/health/health.h"
#include "core/io/log_file.h"
#include "core/parallel/mpi_session.h"
#include "core/scene/scene.h"
#include "core/util/error_line.h"
#include "mpm/solver/standalone_run.h"
#include "common/scene_command_line.h"

using namespace mpmice;

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  const auto line = apps::parseSceneCommandLine(
      argc, argv, session.world().root(), "mpm_solver",
      "Runs a solid-only scene with the explicit Material Point Method, or the solid side of an "
      "MPM-ICE run when started in one MPMD launch with ice_solver (or OpenFOAM, coupling.fluid: "
      "openfoam). Progress lines, HDF5/XDMF output, the energies CSV and probes go to the scene's "
      "output directory; errors name file, line and key (exit 1).",
      "  mpm_solver configs/mpm_vibrating_bar.yaml\n"
      "  scripts/mpirun -np 4 mpm_solver configs/mpm_colliding_disks.yaml\n"
      "  scripts/mpirun -np 1 mpm_solver s.yaml : -np 1 ice_solver s.yaml   (coupled)\n");
  if (line.exit) return *line.exit;
  // Known once the launch is joined: in an MPMD launch an input error found by this program
  // alone must reach the terminal from this program's rank 0 and end the whole launch (the peer
  // would otherwise wait its coupling.timeout for a participant that has gone).
  bool coupled = false, localRoot = session.world().root();
  std::unique_ptr<core::LogFile> logFile;  // <output>/log.mpm_solver: what this program prints, errors included
  try {
    // 1. Scene and launch.
    const core::Scene scene = core::loadScene(line.scene);
    const auto participant = coupler::Participant::join(session.world(), "mpm", scene.coupling.timeout);
    coupled = participant.coupled();
    localRoot = participant.local().root();
    const auto lock = coupler::lockParticipantOutput(participant, scene, "mpm_solver");
    logFile = core::LogFile::teeProgramOutput(participant.local(), scene, "mpm_solver");  // after the lock
    const bool fileLoads = std::any_of(scene.loads.begin(), scene.loads.end(),
                                       [](const core::LoadSpec& l) { return l.type == core::LoadType::File; });
    if (participant.coupled() && fileLoads)
      throw std::invalid_argument("loads: a file load (the sequential workflow) applies to mpm_solver run alone; "
                                  "a coupled run gets its fluid forces from the peer (remove the file load or the peer)");
    if (participant.coupled()) {
      if (scene.coupling.fluid == core::FluidSolver::OpenFoam) {
        try {
          return coupler::runSurfaceSolidParticipant(participant, scene, std::cout, line.restart);
        } catch (const core::HealthError& ex) {  // only this side knows: end the launch
          if (ex.reporter()) core::writeErrorLine("mpm_solver", ex.what());
          std::fflush(stderr);
          core::MpiSession::abortAll(1);
        } catch (const std::invalid_argument& ex) {  // only this side knows (e.g. the fluid's case disagrees)
          core::writeErrorLine("mpm_solver", ex.what());
          std::fflush(stderr);
          core::MpiSession::abortAll(1);
        }
      }
      return coupler::runSolidParticipant(participant, scene, std::cout, line.restart);
    }
    std::function<void(mpm::MpmSolver&)> prepare;
    if (fileLoads) prepare = [](mpm::MpmSolver& mpm) { (void)coupler::applyFileLoads(mpm, std::cout); };
    return mpm::runStandalone(scene, participant.local(), std::cout, line.restart, prepare);  // 2.
  } catch (const core::SceneError& ex) {
    if (session.world().root()) std::fprintf(stderr, "%s\n", ex.what());
    return 1;
  } catch (const core::HealthError& ex) {  // every rank (of both programs, coupled) throws it: one prints
    if (ex.reporter()) core::writeErrorLine("mpm_solver", ex.what());
    return 1;
  } catch (const std::invalid_argument& ex) {  // bad input: every rank of this program throws the same
    if (localRoot) core::writeErrorLine("mpm_solver", ex.what());
    std::fflush(stderr);
    if (coupled) core::MpiSession::abortAll(1);  // only this side knows: end the launch now
    return 1;
  } catch (const std::exception& ex) {  // may be one rank only (a coupling timeout): end the launch
    core::writeErrorLine("mpm_solver", ex.what());
    std::fflush(stderr);
    if (session.world().size() == 1) return 1;  // alone: no peer to wake (MPI_Abort would add Open MPI's noise)
    core::MpiSession::abortAll(1);
  }
  return 0;
}
