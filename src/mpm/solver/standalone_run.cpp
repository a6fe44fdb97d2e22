#include "mpm/solver/standalone_run.h"

#include <memory>

#include "core/io/csv_writer.h"
#include "core/io/run_checkpoints.h"
#include "core/io/run_record.h"
#include "core/time/time_loop.h"
#include "core/util/progress.h"
#include "mpm/solver/health_check.h"
#include "mpm/solver/mpm_output.h"
#include "mpm/solver/mpm_solver.h"
#include "mpm/solver/probes.h"

namespace mpmice::mpm {

int runStandalone(const core::Scene& scene, const core::Comm& comm, std::ostream& log, const std::string& restart,
                  const std::function<void(MpmSolver&)>& prepare) {
  MpmSolver solver(scene, comm);
  core::RunCheckpoints checkpoints(scene, comm, scene.name, "mpm_solver", restart, &log);
  const core::CheckpointData* resumed = checkpoints.resumed();
  if (resumed) solver.loadCheckpoint(*resumed, "mpm");
  core::RunRecord record(scene, comm, "mpm_solver");
  const long long np = solver.globalParticleCount();
  core::Progress progress(log, comm, solver.time(), scene.time.end,
                          core::ProgressOptions{2.0, 0, scene.time.max_steps, solver.stepCount()});
  progress.start(scene.name, scene.mesh.describe(), comm.size());
  if (comm.root())
    for (const std::string& w : solver.geometryWarnings()) log << "warning: " << w << "\n";
  if (comm.root())
    log << "  particles: " << np << "\n  shape function: " << scene.mpm.shape_function << ", update: "
        << scene.mpm.update << ", flip: " << scene.mpm.flip << ", damping: " << scene.mpm.damping
        << " 1/s, cfl: " << scene.time.cfl << "\n"
        << std::flush;
  if (prepare) prepare(solver);
  // Output (collective) and the energies CSV (flushed row by row).
  std::unique_ptr<MpmOutput> output;
  std::unique_ptr<core::CsvWriter> csv;
  if (scene.output.enabled) {
    output = std::make_unique<MpmOutput>(solver);
    const std::string path = scene.output.directory + "/" + scene.name + "_energies.csv";
    if (resumed) {
      core::CsvWriter::cutForResume(comm, path, static_cast<std::int64_t>(resumed->scalar("run.energies_csv")));
      output->resumeIndex(resumed->text("run.xdmf"));
    }
    csv = std::make_unique<core::CsvWriter>(comm, path,
                                            std::vector<std::string>{"step", "time", "kinetic", "strain", "total"}, 0,
                                            resumed ? core::CsvWriter::Mode::Append : core::CsvWriter::Mode::Truncate);
    if (comm.root()) log << "  output: " << output->xdmfPath() << " (energies: " << path << ")\n" << std::flush;
  }
  auto write = [&] {
    const auto e = solver.energies();  // collective
    if (csv) csv->row({double(solver.stepCount()), solver.time(), e.kinetic, e.strain, e.total()});
    if (output) output->write(solver);
  };
  core::OutputSchedule outputs(scene.output.interval, scene.time.end);
  if (resumed) {
    outputs.resume(resumed->get("run.outputs"));
  } else if (outputs.due(0.0) && output) {
    solver.projectToGrid();  // node fields of the initial state
    write();
  }
  // Collective; null without probes.
  const auto probes =
      ProbeRecorder::fromScene(solver, resumed ? static_cast<std::int64_t>(resumed->scalar("run.probes_csv")) : -1);
  if (probes && !resumed) probes->record(solver);
  auto checkpoint = [&](bool last) {
    if (!checkpoints.due(solver.time(), last)) return;
    core::CheckpointData data;
    solver.saveCheckpoint(data, "mpm");
    data.put("run.outputs", outputs.position());
    data.put("run.energies_csv", static_cast<double>(csv ? csv->length() : 0));
    data.put("run.probes_csv", static_cast<double>(probes ? probes->csvLength() : 0));
    data.putText("run.xdmf", output ? output->indexState() : std::string());
    checkpoints.write(data, solver.time(), solver.stepCount());
  };
  while (core::goesOn(solver.time(), solver.stepCount(), scene.time.end, scene.time.max_steps)) {
    const double dt = solver.advance(outputs.landingTarget(solver.time(), solver.stableTimeStep()));
    checkHealth(solver);  // collective: every rank stops on a non-physical state
    if (solver.removedLastStep() > 0 && comm.root()) log << solver.removalReport() << "\n" << std::flush;
    if (probes) probes->record(solver);
    if (outputs.due(solver.time())) write();
    progress.step(static_cast<int>(solver.stepCount()), solver.time(), dt, {},
                  core::reached(solver.time(), scene.time.end));
    const bool last = !core::goesOn(solver.time(), solver.stepCount(), scene.time.end, scene.time.max_steps);
    if (last && !outputs.written(solver.time()) && outputs.due(solver.time(), true)) write();  // time.max_steps
    checkpoint(last);
  }
  if (!outputs.written(solver.time()) && outputs.due(solver.time(), true)) write();  // no step taken
  record.completed();
  const auto e = solver.energies();
  const ParticleOutflow out = solver.outflow();  // collective
  progress.finish(static_cast<int>(solver.stepCount()), solver.time(), static_cast<double>(np), "particle-steps");
  if (comm.root())
    log << "  energy: kinetic " << e.kinetic << ", strain " << e.strain << ", total " << e.total() << "\n" << std::flush;
  if (comm.root() && out.count > 0) log << outflowSummary(out) << std::flush;
  return 0;
}

}  // namespace mpmice::mpm
