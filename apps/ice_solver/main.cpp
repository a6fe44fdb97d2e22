// ice_solver: runs a fluid-only scene with multi-material ICE, or the fluid side of an MPM-ICE
// run when started in one MPMD launch with mpm_solver
// (scripts/mpirun -np 1 mpm_solver s.yaml : -np 1 ice_solver s.yaml).
//
// Sample runs:
//   ice_solver configs/ice_sod.yaml
//   scripts/mpirun -np 4 ice_solver configs/ice_water_air.yaml
//
// 1. Start MPI and read the scene.  2. Build the solver (initial state, equilibrium pressure).
// 3. Print the scene, mesh, materials, ranks.  4. Step to time.end with progress lines and ETA,
// writing HDF5/XDMF output and a CSV of total mass, momentum and energy at each output time.
// 5. Print the summary (steps, wall time, cell-steps/s). Errors: message on stderr, exit code 1.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/io/csv_writer.h"
#include "core/io/output_writer.h"
#include "core/parallel/mpi_session.h"
#include "core/scene/scene.h"
#include "coupler/launch/participant.h"
#include "couplings/volume/fluid/fluid_participant.h"
#include "ice/solver/ice_solver.h"
#include "core/util/progress.h"

using namespace mpmice;

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  if (argc != 2) {
    if (session.world().root()) std::cerr << "usage: ice_solver scene.yaml\n";
    return 2;
  }
  try {
    // 1. The scene; join the launch: with a peer (mpm_solver), run the coupled fluid side.
    const core::Scene scene = core::loadScene(argv[1]);
    const auto participant = coupler::Participant::join(session.world(), "ice", scene.coupling.timeout);
    if (participant.coupled()) return coupler::runFluidParticipant(participant, scene, std::cout);
    const core::Comm comm = participant.local();
    if (!scene.solids().empty() && comm.root())
      std::cout << "note: the scene has solid materials; ice_solver alone treats them as absent external "
                   "materials (run the coupler for MPM-ICE)\n";
    // 2. The solver.
    ice::IceSolver solver(scene, comm);
    // 3. What runs.
    if (comm.root()) {
      std::cout << "scene      " << scene.name << " (" << scene.file << ")\n"
                << "mesh       " << scene.mesh.describe() << "\n"
                << "ranks      " << comm.size() << "\n"
                << "ice        advection " << scene.ice.advection << " (" << scene.ice.limiter << "), pressure "
                << scene.ice.pressure_solver << "\n";
      for (const auto& m : scene.materials)
        std::cout << "material   " << m.name << ": " << m.eos.type << ", cv " << m.specific_heat << "\n";
    }
    // 4. Steps, output, totals.
    const std::string dir = scene.output.directory;
    std::unique_ptr<core::OutputWriter> writer;
    std::unique_ptr<core::CsvWriter> csv;
    if (scene.output.enabled) {
      writer = std::make_unique<core::OutputWriter>(comm, solver.decomposition(), dir, scene.name);
      csv = std::make_unique<core::CsvWriter>(comm, dir + "/" + scene.name + "_totals.csv",
                                              std::vector<std::string>{"step", "time", "mass", "momentum_x",
                                                                       "momentum_y", "momentum_z", "energy"});
    }
    long lastOutput = -1;
    auto output = [&]() {
      lastOutput = solver.steps();
      const ice::Totals t = solver.totals();
      if (!writer) return;
      const std::vector<core::Field> fields = solver.outputFields();
      std::vector<const core::Field*> ptrs;
      for (const auto& f : fields) ptrs.push_back(&f);
      writer->writeStep(static_cast<int>(solver.steps()), solver.time(), ptrs);
      csv->row({double(solver.steps()), solver.time(), t.mass, t.momentum[0], t.momentum[1], t.momentum[2],
                t.energy});
    };
    core::Progress progress(std::cout, comm, 0.0, scene.time.end);
    progress.start(scene.name, scene.mesh.describe(), comm.size());
    output();
    const double interval = scene.output.interval;
    double nextOut = interval > 0 ? interval : scene.time.end;
    const long maxSteps = scene.time.max_steps;
    while (solver.time() < scene.time.end * (1 - 1e-12) && (maxSteps == 0 || solver.steps() < maxSteps)) {
      solver.step();
      double maxIt = 0;
      const auto& it = solver.state().iters;
      core::forEach(solver.ownedBox(), [&](int i, int j, int k) { maxIt = std::max(maxIt, it(i, j, k)); });
      progress.step(static_cast<int>(solver.steps()), solver.time(), solver.dt(), {{"p_iters", comm.max(maxIt)}});
      if (solver.time() >= nextOut * (1 - 1e-12)) {
        output();
        nextOut += interval > 0 ? interval : scene.time.end;
      }
    }
    if (lastOutput != solver.steps()) output();  // the last step, when no interval ended there
    // 5. Summary.
    progress.finish(static_cast<int>(solver.steps()), solver.time(), double(scene.mesh.numCells()), "cell-steps");
    if (comm.root() && writer) std::cout << "output     " << writer->xdmfPath() << "\n";
  } catch (const core::SceneError& e) {
    if (session.world().root()) std::cerr << e.what() << "\n";
    return 1;
  } catch (const std::invalid_argument& e) {  // bad input: every rank throws the same
    if (session.world().root()) std::cerr << "ice_solver: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {  // may be one rank only (a coupling timeout): end the launch
    std::cerr << "ice_solver: error: " << e.what() << std::endl;
    core::MpiSession::abortAll(1);
  }
  return 0;
}
