// ice_solver: runs a fluid-only scene with multi-material ICE, or the fluid side of an MPM-ICE
// run when started in one MPMD launch with mpm_solver
// (scripts/mpirun -np 1 mpm_solver s.yaml : -np 1 ice_solver s.yaml).
//
// Sample runs:
//   ice_solver configs/ice_sod.yaml
//   scripts/mpirun -np 4 ice_solver configs/ice_water_air.yaml
//   ice_solver --help                  (or --version)
//
// 1. Start MPI and read the scene; join the launch: with a peer (mpm_solver), run the coupled
//    fluid side (src/couplings/volume/fluid/fluid_participant.h).
// 2. Alone: run the scene (src/ice/solver/standalone_run.h: progress lines with ETA, HDF5/XDMF
//    output, totals CSV, summary). Errors: message on stderr, exit code 1.
#include <cstdio>
#include <iostream>
#include <memory>

#include "core/parallel/mpi_session.h"
#include "core/scene/scene.h"
#include "core/util/error_line.h"
#include "coupler/launch/output_lock.h"
#include "coupler/launch/participant.h"
#include "couplings/volume/fluid/fluid_participant.h"
#include "core/health/health.h"
#include "core/io/log_file.h"
#include "ice/solver/standalone_run.h"
#include "common/scene_command_line.h"

using namespace mpmice;

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  const auto line = apps::parseSceneCommandLine(
      argc, argv, session.world().root(), "ice_solver",
      "Runs a fluid-only scene with multi-material ICE, or the fluid side of an MPM-ICE run when "
      "started in one MPMD launch with mpm_solver. Progress lines with ETA, HDF5/XDMF output, the "
      "totals CSV and a summary go to the scene's output directory; errors print on stderr (exit 1).",
      "  ice_solver configs/ice_sod.yaml\n"
      "  scripts/mpirun -np 4 ice_solver configs/ice_water_air.yaml\n"
      "  scripts/mpirun -np 1 mpm_solver s.yaml : -np 1 ice_solver s.yaml   (coupled)\n");
  if (line.exit) return *line.exit;
  // Known once the launch is joined: in an MPMD launch an input error found by this program
  // alone must reach the terminal from this program's rank 0 and end the whole launch (the peer
  // would otherwise wait its coupling.timeout for a participant that has gone).
  bool coupled = false, localRoot = session.world().root();
  std::unique_ptr<core::LogFile> logFile;  // <output>/log.ice_solver: what this program prints, errors included
  try {
    // 1. The scene; join the launch.
    const core::Scene scene = core::loadScene(line.scene);
    const auto participant = coupler::Participant::join(session.world(), "ice", scene.coupling.timeout);
    coupled = participant.coupled();
    localRoot = participant.local().root();
    const auto lock = coupler::lockParticipantOutput(participant, scene, "ice_solver");
    logFile = core::LogFile::teeProgramOutput(participant.local(), scene, "ice_solver");  // after the lock
    if (participant.coupled()) return coupler::runFluidParticipant(participant, scene, std::cout, line.restart);
    return ice::runStandalone(scene, participant.local(), std::cout, line.restart);  // 2.
  } catch (const core::SceneError& e) {
    if (session.world().root()) std::cerr << e.what() << "\n";
    return 1;
  } catch (const core::HealthError& e) {  // every rank (of both programs, coupled) throws it: one prints
    if (e.reporter()) core::writeErrorLine("ice_solver", e.what());
    return 1;
  } catch (const std::invalid_argument& e) {  // bad input: every rank of this program throws the same
    if (localRoot) core::writeErrorLine("ice_solver", e.what());
    if (coupled) core::MpiSession::abortAll(1);  // only this side knows: end the launch now
    return 1;
  } catch (const std::exception& e) {  // may be one rank only (a coupling timeout): end the launch
    core::writeErrorLine("ice_solver", e.what());
    if (session.world().size() == 1) return 1;  // alone: no peer to wake (MPI_Abort would add Open MPI's noise)
    core::MpiSession::abortAll(1);
  }
  return 0;
}
