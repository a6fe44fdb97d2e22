// mpmice: the in-process MPM-ICE run. libmpm and libice in one process with in-memory exchange;
// the reference for the MPMD launch of mpm_solver + ice_solver (same schedule, same time loop,
// same numbers).
//
// Sample runs:  mpmice configs/pressurized_cylinder.yaml
//               scripts/mpirun -np 2 mpmice configs/pressurized_cylinder.yaml
//               mpmice --help                      (or --version)
// 1. Start MPI, read and validate the scene (errors name file, line and key; exit 2).
// 2. Run it (src/couplings/volume/monolithic/monolithic_run.h): both solvers on one
//    decomposition, the scene's coupling schedule, output at each output time.
#include <iostream>
#include <memory>

#include "core/health/health.h"
#include "core/io/log_file.h"
#include "core/io/run_lock.h"
#include "core/parallel/mpi_session.h"
#include "core/scene/scene.h"
#include "core/util/error_line.h"
#include "couplings/volume/monolithic/monolithic_run.h"
#include "common/scene_command_line.h"

using namespace mpmice;

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  const core::Comm comm = session.world();
  const auto line = apps::parseSceneCommandLine(
      argc, argv, comm.root(), "mpmice",
      "The in-process MPM-ICE run: MPM and ICE in one process with in-memory exchange, both "
      "solvers on one decomposition with the scene's coupling schedule; the reference for the "
      "MPMD launch of mpm_solver + ice_solver (same schedule, same time loop, same numbers). "
      "Scene errors name file, line and key (exit 2).",
      "  mpmice configs/pressurized_cylinder.yaml\n"
      "  scripts/mpirun -np 2 mpmice configs/pressurized_cylinder.yaml\n");
  if (line.exit) return *line.exit;
  std::unique_ptr<core::LogFile> logFile;  // <output>/log.mpmice: what it prints, errors included
  try {
    const core::Scene scene = core::loadScene(line.scene);  // 1.
    const auto lock = core::lockOutputDirectory(comm, scene, "mpmice", &std::cerr);  // every rank learns a refusal
    logFile = core::LogFile::teeProgramOutput(comm, scene, "mpmice");  // after the lock
    return coupler::runMonolithic(scene, comm, std::cout, line.restart);  // 2.
  } catch (const core::SceneError& e) {
    if (comm.root()) std::cerr << e.what() << "\n";
    return 2;
  } catch (const core::HealthError& e) {  // every rank throws it: one prints, all end 1
    if (e.reporter()) core::writeErrorLine("mpmice", e.what());
    return 1;
  } catch (const core::RunLockHeld& e) {
    if (comm.root()) core::writeErrorLine("mpmice", e.what());
    return 1;
  } catch (const std::exception& e) {
    core::writeErrorLine("mpmice", e.what());
    // One rank has no peer to wake: end with status 1 (MPI_Abort in a process started without
    // mpirun makes Open MPI print an error of its own after the message).
    if (comm.size() == 1) return 1;
    core::MpiSession::abortAll(1);
  }
}
