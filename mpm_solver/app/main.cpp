// mpm_solver: runs a solid-only scene with the explicit Material Point Method (uncoupled).
//
// Sample runs:  mpm_solver configs/mpm_vibrating_bar.yaml
//               scripts/mpirun -np 4 mpm_solver configs/mpm_colliding_disks.yaml
// 1. Read and validate the scene (errors name file, line and key; exit 1).
// 2. Build the solver: decomposition over the ranks, particles from the geometry.
// 3. Step to time.end with progress lines; write energies (CSV) at each output time.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "parallel/mpi_session.h"
#include "scene/scene.h"
#include "solver/mpm_solver.h"

using namespace mpmice;

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  const core::Comm comm = session.world();
  if (argc != 2) {
    if (comm.root()) std::fprintf(stderr, "usage: mpm_solver scene.yaml\n");
    return 2;
  }
  try {
    // 1. Scene.
    const core::Scene scene = core::loadScene(argv[1]);
    // 2. Solver.
    mpm::MpmSolver solver(scene, comm);
    const long long np = solver.globalParticleCount();
    if (comm.root()) {
      std::printf("mpm_solver: scene '%s' (%s)\n  mesh: %s\n  particles: %lld, ranks: %d\n"
                  "  shape function: %s, update: %s, flip: %g, damping: %g 1/s\n  end time: %g s, cfl: %g\n",
                  scene.name.c_str(), scene.file.c_str(), scene.mesh.describe().c_str(), np, comm.size(),
                  scene.mpm.shape_function.c_str(), scene.mpm.update.c_str(), scene.mpm.flip, scene.mpm.damping,
                  scene.time.end, scene.time.cfl);
      std::fflush(stdout);
    }
    // 3. Time loop.
    std::ofstream csv;
    if (comm.root() && scene.output.enabled) {
      std::filesystem::create_directories(scene.output.directory);
      const std::string path = scene.output.directory + "/" + scene.name + "_energies.csv";
      csv.open(path);
      csv << "step,time,kinetic,strain,total\n";
      std::printf("  energies: %s\n", path.c_str());
    }
    auto writeEnergies = [&] {
      const auto e = solver.energies();
      if (csv.is_open())
        csv << solver.stepCount() << ',' << solver.time() << ',' << e.kinetic << ',' << e.strain << ','
            << e.total() << '\n';
    };
    writeEnergies();
    const auto t0 = std::chrono::steady_clock::now();
    double nextOut = scene.output.interval > 0 ? scene.output.interval : scene.time.end;
    double nextPrint = 0;
    while (solver.time() < scene.time.end * (1 - 1e-12)) {
      if (scene.time.max_steps > 0 && solver.stepCount() >= scene.time.max_steps) break;
      solver.advance(std::min(scene.time.end, nextOut));
      if (solver.time() >= nextOut * (1 - 1e-12)) {
        writeEnergies();
        nextOut += scene.output.interval > 0 ? scene.output.interval : scene.time.end;
      }
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (comm.root() && (wall >= nextPrint || solver.time() >= scene.time.end * (1 - 1e-12))) {
        const double frac = solver.time() / scene.time.end;
        std::printf("  step %ld  t = %.6g s  (%.1f%%)  wall %.1f s  ETA %.1f s\n", solver.stepCount(), solver.time(),
                    100 * frac, wall, frac > 0 ? wall * (1 - frac) / frac : 0.0);
        std::fflush(stdout);
        nextPrint = wall + 2.0;
      }
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto e = solver.energies();
    if (comm.root())
      std::printf("done: %ld steps, t = %g s, wall %.2f s, %.3g particle-steps/s\n  energy: kinetic %.6g, "
                  "strain %.6g, total %.6g\n",
                  solver.stepCount(), solver.time(), wall, double(np) * double(solver.stepCount()) / wall, e.kinetic,
                  e.strain, e.total());
  } catch (const std::exception& ex) {
    if (comm.root()) std::fprintf(stderr, "mpm_solver: error: %s\n", ex.what());
    return 1;
  }
  return 0;
}
