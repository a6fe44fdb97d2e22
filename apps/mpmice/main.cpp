// mpmice: the monolithic MPM-ICE driver. libmpm and libice in one process with in-memory
// exchange; the reference for the MPMD launch of mpm_solver + ice_solver (same numerics).
//
// Sample runs:  mpmice configs/pressurized_cylinder.yaml
//               scripts/mpirun -np 2 mpmice configs/pressurized_cylinder.yaml
// 1. Start MPI, read and validate the scene (errors name file, line and key; exit 2).
// 2. Build both solvers on the same decomposition.
// 3. Step to time.end: monolithic-style schedule, four in-memory exchange points per step.
// 4. Output at each output time: HDF5/XDMF (fluid fields, particles), conservation CSV; the
//    coupling log and the probes (output.probes: <scene>_probes.csv) at t = 0 and every step.
#include <algorithm>
#include <iostream>
#include <memory>

#include "couplings/volume/monolithic/monolithic_driver.h"
#include "couplings/volume/common/run_output.h"
#include "core/parallel/mpi_session.h"
#include "core/scene/scene.h"
#include "mpm/solver/probes.h"
#include "core/util/progress.h"

using namespace mpmice;

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  const core::Comm comm = session.world();
  if (argc != 2) {
    if (comm.root()) std::cerr << "usage: mpmice scene.yaml\n";
    return 2;
  }
  try {
    // 1. Scene.
    const core::Scene scene = core::loadScene(argv[1]);
    // 2. Solvers.
    coupler::MonolithicDriver driver(scene, comm);
    const long long particles = driver.mpm().globalParticleCount();
    core::Progress progress(std::cout, comm, 0.0, scene.time.end, core::ProgressOptions{2.0, 0});
    progress.start(scene.name + " (mpmice, monolithic, " + std::to_string(particles) + " particles)",
                   scene.mesh.describe(), comm.size());
    // 3-4. Steps and output.
    coupler::RunOutput out(scene, comm, driver.mpm().decomposition());
    auto write = [&] {
      const std::vector<core::Field> fields = driver.ice().outputFields();
      std::vector<const core::Field*> ptrs;
      for (const auto& f : fields) ptrs.push_back(&f);
      const core::ParticleOutput parts = driver.solid().particleOutput();
      out.writeFields(driver.steps(), driver.time(), ptrs, &parts);
      out.writeTotals(driver.steps(), driver.time(), driver.solid().totals(), driver.fluid().totals());
    };
    if (out.due(0.0)) write();
    // The per-step coupling log: iterations, convergence and the residual of each measure.
    std::unique_ptr<core::CsvWriter> log;
    if (scene.output.enabled) {
      std::vector<std::string> cols{"step", "time", "dt", "iterations", "converged"};
      for (const auto& f : driver.schedule().measuredFields()) cols.push_back("residual_" + f);
      log = std::make_unique<core::CsvWriter>(comm, scene.output.directory + "/" + scene.name + "_coupling.csv", cols);
    }
    // The probes' particles (output.probes): position and displacement at t = 0 and every step.
    const auto probes = mpm::ProbeRecorder::fromScene(driver.mpm());
    if (probes) probes->record(driver.mpm());
    double tPrev = 0;
    long unconverged = 0, iterations = 0;
    driver.run(scene.time.end, [&] {
      const coupler::StepReport& r = driver.lastReport();
      iterations += r.iterations;
      if (!r.converged) {
        ++unconverged;
        if (comm.root())
          std::cout << "coupling: step " << driver.steps() << " accepted unconverged after " << r.iterations
                    << " iterations (coupling.accept_unconverged)\n";
      }
      if (log) {
        std::vector<double> row{double(driver.steps()), driver.time(), driver.time() - tPrev, double(r.iterations),
                                r.converged ? 1.0 : 0.0};
        row.insert(row.end(), r.residuals.begin(), r.residuals.end());
        log->row(row);
      }
      if (probes) probes->record(driver.mpm());
      if (out.due(driver.time())) write();
      progress.step(static_cast<int>(driver.steps()), driver.time(), driver.time() - tPrev,
                    {{"iters", double(r.iterations)}});
      tPrev = driver.time();
    });
    if (comm.root())
      std::cout << "coupling: schedule " << scene.coupling.schedule << ", " << iterations << " iterations in "
                << driver.steps() << " steps (" << double(iterations) / double(std::max(1L, driver.steps()))
                << " per step), " << unconverged << " steps accepted unconverged\n";
    progress.finish(static_cast<int>(driver.steps()), driver.time(), double(scene.mesh.numCells()));
    return 0;
  } catch (const core::SceneError& e) {
    if (comm.root()) std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mpmice: " << e.what() << "\n";
    core::MpiSession::abortAll(1);
  }
}
