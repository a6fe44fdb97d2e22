// mpm_solver: runs a solid-only scene with the explicit Material Point Method, or the solid side
// of an MPM-ICE run when started in one MPMD launch with ice_solver.
//
// Sample runs:  mpm_solver configs/mpm_vibrating_bar.yaml
//               scripts/mpirun -np 4 mpm_solver configs/mpm_colliding_disks.yaml
//               scripts/mpirun -np 1 mpm_solver s.yaml : -np 1 ice_solver s.yaml   (coupled)
// 1. Read and validate the scene (errors name file, line and key; exit 1); join the launch
//    (src/coupler/launch/participant.h): with a peer, run the coupled solid side and stop there
//    (MPM-ICE: src/couplings/volume/solid; a surface coupling with OpenFOAM: src/couplings/surface/solid).
// 2. Build the solver: decomposition over the ranks, particles from the geometry.
// 3. Step to time.end with progress lines (src/core/util/progress.h). At t = 0, at every
//    output.interval and at the last step (unless output.enabled is false): one HDF5 file of
//    particles and grid nodes plus the XDMF index (solver/mpm_output.h), and a row of energies in
//    <directory>/<scene>_energies.csv. Probes (output.probes), when given: the position and
//    displacement of their particles at t = 0 and after every step in <directory>/<scene>_probes.csv.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "coupler/launch/participant.h"
#include "coupler/launch/timed_wait.h"
#include "couplings/volume/solid/solid_participant.h"
#include "couplings/surface/solid/surface_solid_participant.h"
#include "core/parallel/mpi_session.h"
#include "core/scene/scene.h"
#include "mpm/solver/mpm_output.h"
#include "mpm/solver/mpm_solver.h"
#include "mpm/solver/probes.h"
#include "core/util/progress.h"

using namespace mpmice;

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  if (argc != 2) {
    if (session.world().root()) std::fprintf(stderr, "usage: mpm_solver scene.yaml\n");
    return 2;
  }
  try {
    // 1. Scene and launch.
    const core::Scene scene = core::loadScene(argv[1]);
    const auto participant = coupler::Participant::join(session.world(), "mpm", scene.coupling.timeout);
    if (participant.coupled()) {
      if (scene.coupling.fluid == core::FluidSolver::OpenFoam) {
        try {
          return coupler::runSurfaceSolidParticipant(participant, scene, std::cout);
        } catch (const std::invalid_argument& ex) {  // only this side knows (e.g. the fluid's case disagrees)
          std::fprintf(stderr, "mpm_solver: error: %s\n", ex.what());
          std::fflush(stderr);
          core::MpiSession::abortAll(1);
        }
      }
      return coupler::runSolidParticipant(participant, scene, std::cout);
    }
    const core::Comm comm = participant.local();
    // 2. Solver.
    mpm::MpmSolver solver(scene, comm);
    const long long np = solver.globalParticleCount();
    core::Progress progress(std::cout, comm, 0.0, scene.time.end, core::ProgressOptions{2.0, 0});
    progress.start(scene.name, scene.mesh.describe(), comm.size());
    if (comm.root()) {
      std::printf("  particles: %lld\n  shape function: %s, update: %s, flip: %g, damping: %g 1/s, cfl: %g\n", np,
                  scene.mpm.shape_function.c_str(), scene.mpm.update.c_str(), scene.mpm.flip, scene.mpm.damping,
                  scene.time.cfl);
      std::fflush(stdout);
    }
    // 3. Output (collective) and time loop.
    std::unique_ptr<mpm::MpmOutput> output;
    std::ofstream csv;
    if (scene.output.enabled) {
      output = std::make_unique<mpm::MpmOutput>(solver);
      if (comm.root()) {
        const std::string path = scene.output.directory + "/" + scene.name + "_energies.csv";
        csv.open(path);
        csv << "step,time,kinetic,strain,total\n";
        std::printf("  output: %s (energies: %s)\n", output->xdmfPath().c_str(), path.c_str());
        std::fflush(stdout);
      }
    }
    auto writeOutput = [&] {
      const auto e = solver.energies();  // collective
      if (csv.is_open())
        csv << solver.stepCount() << ',' << solver.time() << ',' << e.kinetic << ',' << e.strain << ','
            << e.total() << '\n';
      if (output) output->write(solver);
    };
    if (output) {
      solver.projectToGrid();  // node fields of the initial state
      writeOutput();
    }
    const auto probes = mpm::ProbeRecorder::fromScene(solver);  // collective; null without probes
    if (probes) probes->record(solver);
    const double interval = scene.output.interval > 0 ? scene.output.interval : scene.time.end;
    double nextOut = interval;
    const double tEnd = scene.time.end * (1 - 1e-12);
    bool written = true;
    while (solver.time() < tEnd) {
      if (scene.time.max_steps > 0 && solver.stepCount() >= scene.time.max_steps) break;
      const double dt = solver.advance(std::min(scene.time.end, nextOut));
      if (probes) probes->record(solver);
      written = false;
      if (solver.time() >= nextOut * (1 - 1e-12)) {
        writeOutput();
        written = true;
        while (nextOut <= solver.time() * (1 + 1e-12)) nextOut += interval;
      }
      progress.step(static_cast<int>(solver.stepCount()), solver.time(), dt, {}, solver.time() >= tEnd);
    }
    if (!written) writeOutput();  // stopped by time.max_steps between output times
    const auto e = solver.energies();
    progress.finish(static_cast<int>(solver.stepCount()), solver.time(), static_cast<double>(np), "particle-steps");
    if (comm.root())
      std::printf("  energy: kinetic %.6g, strain %.6g, total %.6g\n", e.kinetic, e.strain, e.total());
  } catch (const core::SceneError& ex) {
    if (session.world().root()) std::fprintf(stderr, "%s\n", ex.what());
    return 1;
  } catch (const std::invalid_argument& ex) {  // bad input: every rank throws the same
    if (session.world().root()) std::fprintf(stderr, "mpm_solver: error: %s\n", ex.what());
    return 1;
  } catch (const std::exception& ex) {  // may be one rank only (a coupling timeout): end the launch
    std::fprintf(stderr, "mpm_solver: error: %s\n", ex.what());
    std::fflush(stderr);
    core::MpiSession::abortAll(1);
  }
  return 0;
}
