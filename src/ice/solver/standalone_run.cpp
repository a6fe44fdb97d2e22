#include "ice/solver/standalone_run.h"

#include <algorithm>
#include <memory>

#include "core/io/csv_writer.h"
#include "core/io/run_checkpoints.h"
#include "core/io/run_record.h"
#include "core/io/output_selection.h"
#include "core/io/output_writer.h"
#include "core/time/time_loop.h"
#include "core/util/progress.h"
#include "ice/solver/health_check.h"
#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

int runStandalone(const core::Scene& scene, const core::Comm& comm, std::ostream& log, const std::string& restart) {
  if (!scene.solids().empty() && comm.root())
    log << "note: the scene has solid materials; ice_solver alone treats them as absent external "
           "materials (run the coupler for MPM-ICE)\n";
  IceSolver solver(scene, comm, /*coupledStart=*/false);
  core::RunCheckpoints checkpoints(scene, comm, scene.name, "ice_solver", restart, &log);
  const core::CheckpointData* resumed = checkpoints.resumed();
  if (resumed) solver.loadCheckpoint(*resumed, "ice");
  core::RunRecord record(scene, comm, "ice_solver");
  if (comm.root()) {
    log << "scene      " << scene.name << " (" << scene.file << ")\n"
        << "mesh       " << scene.mesh.describe() << "\n"
        << "ranks      " << comm.size() << "\n"
        << "ice        advection " << scene.ice.advection << " (" << scene.ice.limiter << "), pressure "
        << scene.ice.pressure_solver << "\n";
    for (const auto& m : scene.materials)
      log << "material   " << m.name << ": " << m.eos.type << ", cv " << m.specific_heat << "\n";
  }
  const std::string dir = scene.output.directory;
  std::unique_ptr<core::OutputWriter> writer;
  std::unique_ptr<core::CsvWriter> csv;
  if (scene.output.enabled) {
    writer = std::make_unique<core::OutputWriter>(comm, solver.decomposition(), dir, scene.name);
    const std::string path = dir + "/" + scene.name + "_totals.csv";
    if (resumed) {
      core::CsvWriter::cutForResume(comm, path, static_cast<std::int64_t>(resumed->scalar("run.totals_csv")));
      writer->resumeIndex(resumed->text("run.xdmf"));
    }
    csv = std::make_unique<core::CsvWriter>(
        comm, path, std::vector<std::string>{"step", "time", "mass", "momentum_x", "momentum_y", "momentum_z", "energy"},
        0, resumed ? core::CsvWriter::Mode::Append : core::CsvWriter::Mode::Truncate);
  }
  // output.fields: refuse a name this program does not offer, before the first step.
  std::vector<std::string> materials;
  for (const auto& m : scene.materials) materials.push_back(m.name);
  core::checkOutputFields(scene.output.fields, solver.outputFieldNames(), materials, "ice_solver");
  auto output = [&] {
    const Totals t = solver.totals();  // collective
    if (!writer) return;
    const std::vector<core::Field> fields =
        solver.outputFields([&](const std::string& n) { return core::outputSelected(scene.output.fields, n, materials); });
    std::vector<const core::Field*> ptrs;
    for (const auto& f : fields) ptrs.push_back(&f);
    writer->writeStep(static_cast<int>(solver.steps()), solver.time(), ptrs);
    csv->row({double(solver.steps()), solver.time(), t.mass, t.momentum[0], t.momentum[1], t.momentum[2], t.energy});
  };
  core::Progress progress(log, comm, solver.time(), scene.time.end,
                          core::ProgressOptions{10.0, 0, scene.time.max_steps, solver.steps()});
  progress.start(scene.name, scene.mesh.describe(), comm.size());
  core::OutputSchedule outputs(scene.output.interval, scene.time.end);
  if (resumed)
    outputs.resume(resumed->get("run.outputs"));
  else if (outputs.due(0.0))
    output();
  auto checkpoint = [&](bool last) {
    if (!checkpoints.due(solver.time(), last)) return;
    core::CheckpointData data;
    solver.saveCheckpoint(data, "ice");
    data.put("run.outputs", outputs.position());
    data.put("run.totals_csv", static_cast<double>(csv ? csv->length() : 0));
    data.putText("run.xdmf", writer ? writer->index().serialize() : std::string());
    checkpoints.write(data, solver.time(), solver.steps());
  };
  while (core::goesOn(solver.time(), solver.steps(), scene.time.end, scene.time.max_steps)) {
    solver.step();
    checkHealth(solver);  // collective: every rank stops on a non-physical state
    core::Progress::Extras extras{{"p_iters", comm.max(double(solver.mostPressureIterations()))}};
    if (solver.semiImplicit()) extras.emplace_back("lin_iters", double(solver.linearIterations()));
    progress.step(static_cast<int>(solver.steps()), solver.time(), solver.dt(), extras);
    if (outputs.due(solver.time())) output();
    const bool last = !core::goesOn(solver.time(), solver.steps(), scene.time.end, scene.time.max_steps);
    if (last && !outputs.written(solver.time()) && outputs.due(solver.time(), true)) output();  // the last step
    checkpoint(last);
  }
  if (!outputs.written(solver.time()) && outputs.due(solver.time(), true)) output();  // no step taken
  record.completed();
  progress.finish(static_cast<int>(solver.steps()), solver.time(), double(scene.mesh.numCells()), "cell-steps");
  if (comm.root() && solver.semiImplicit()) log << solver.pressureSolveSummary(solver.steps()) << "\n";
  if (solver.viscous()) {
    const double heat = comm.sum(solver.viscousHeat());  // collective
    if (comm.root())
      log << "viscous heat " << heat << " J (the kinetic energy the fluids' viscosity turned into heat, this process's "
          << "steps)\n";
  }
  if (comm.root() && writer) log << "output     " << writer->xdmfPath() << "\n";
  return 0;
}

}  // namespace mpmice::ice
