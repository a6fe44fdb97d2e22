#include "couplings/volume/run/volume_run.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "core/health/health.h"
#include "core/io/csv_writer.h"
#include "core/io/output_selection.h"
#include "core/io/run_checkpoints.h"
#include "core/io/run_record.h"
#include "core/time/time_loop.h"
#include "core/util/progress.h"
#include "coupler/launch/launch_watchdog.h"
#include "couplings/volume/common/run_output.h"
#include "couplings/volume/schedule/coupling_schedule.h"
#include "ice/solver/health_check.h"
#include "mpm/mpm_constants.h"
#include "mpm/solver/health_check.h"
#include "mpm/solver/probes.h"

namespace mpmice::coupler {

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// A solid's violation at x in a run that holds the fluid too (mpmice): why the fluid of x's cell is
// not held by the solid (ice::weakExchangeNote), "" when it is, or when another rank owns the cell.
std::string fluidNoteAt(const ice::IceSolver& fluid, const double* x) {
  const core::Mesh& mesh = fluid.mesh();
  int c[3] = {0, 0, 0};
  for (int d = 0; d < mesh.dim(); ++d) {
    if (!std::isfinite(x[d])) return "";  // a particle position that is not finite
    c[d] = std::clamp(mesh.cellOf(d, x[d]), 0, mesh.cells()[d] - 1);
  }
  if (!fluid.ownedBox().contains(c[0], c[1], c[2])) return "";
  const core::Box& sb = fluid.state().press.box();
  for (int r = 0; r < fluid.numMaterials(); ++r) {
    const ice::MaterialState& m = fluid.state().mat[static_cast<std::size_t>(r)];
    if (m.external || !(m.theta.data()[sb.index(c[0], c[1], c[2])] > 0)) continue;
    const std::string note = ice::weakExchangeNote(fluid, c[0], c[1], c[2], r);
    if (!note.empty()) return "; in its cell (" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," +
                              std::to_string(c[2]) + ") of the fluid" + note;
  }
  return "";
}

// The health check of each side present (collective); in an MPMD launch the two programs trade
// their verdicts, so both stop together (the side that found the violation names it), and with
// them this process's compute and exchange seconds of the step (`split`): returns the peer's.
std::array<double, 2> checkHealth(const Sides& sides, Transport& transport, const core::Comm& comm,
                                  const std::string& label, bool mpmd, std::array<double, 2> split) {
  std::string bad;
  double at[3] = {0, 0, 0};
  if (sides.solid) bad = mpm::findViolation(sides.solid->solver(), at);
  if (!bad.empty() && sides.fluid) bad += fluidNoteAt(sides.fluid->solver(), at);
  if (bad.empty() && sides.fluid) bad = ice::findViolation(sides.fluid->solver());
  bad = comm.firstMessage(bad);
  std::vector<double> peer{0.0, 0.0, 0.0};
  if (mpmd) peer = transport.trade({bad.empty() ? 0.0 : 1.0, split[0], split[1]}, "health");
  if (!bad.empty()) throw core::HealthError(mpmd ? label + ": " + bad : bad, comm.root());
  if (peer[0] != 0.0)
    throw core::HealthError(label + ": stopped: the peer program found a non-physical state (its message names it)",
                            comm.root());
  return {peer[1], peer[2]};
}
}  // namespace

int runVolumeCoupling(const core::Scene& scene, const Sides& sides, Transport& transport, const core::Comm& comm,
                      std::ostream& log, const std::string& label, const std::function<void(long)>& afterStep,
                      const std::string& restart) {
  const bool both = sides.solid && sides.fluid;
  const auto schedule = makeSchedule(scene, comm);
  const core::Decomposition& decomp =
      sides.solid ? sides.solid->solver().decomposition() : sides.fluid->solver().decomposition();
  const std::string suffix = both ? "" : sides.solid ? "_solid" : "_fluid";
  core::RunCheckpoints checkpoints(scene, comm, scene.name + suffix,
                                   both ? "mpmice" : sides.solid ? "mpm_solver (coupled)" : "ice_solver (coupled)",
                                   restart, &log);
  const core::CheckpointData* resumed = checkpoints.resumed();
  const std::vector<double> clock =
      resumed ? resumed->get("run.coupled") : std::vector<double>{0.0, 0.0, 0.0, 0.0, 0.0};
  if (clock.size() != 5) throw std::invalid_argument(resumed->source() + ": checkpoint entry 'run.coupled' is malformed");

  core::Progress progress(log, comm, clock[0], scene.time.end,
                          core::ProgressOptions{sides.solid ? 2.0 : 1e30, 0, scene.time.max_steps,
                                                static_cast<long>(clock[1])});
  const long long particles = sides.solid ? sides.solid->solver().globalParticleCount() : 0;
  if (sides.solid)
    progress.start(scene.name + " (" + label + ", schedule " + std::string(core::name(scene.coupling.schedule)) +
                       ", " + std::to_string(particles) + " particles)",
                   scene.mesh.describe(), comm.size());
  if (sides.solid && comm.root())
    for (const std::string& w : sides.solid->solver().geometryWarnings()) log << "warning: " << w << "\n";
  std::vector<std::string> materials;  // output.fields: each side writes its part of the list
  for (const auto& m : scene.materials) materials.push_back(m.name);
  core::RunRecord record(scene, comm, both ? "mpmice" : sides.solid ? "mpm_solver" : "ice_solver", suffix);
  RunOutput out(scene, comm, decomp, suffix, sides.solid != nullptr, resumed);
  auto output = [&](long n, double t) {
    std::vector<core::Field> fields;
    std::vector<const core::Field*> ptrs;
    if (sides.fluid)
      fields = sides.fluid->solver().outputFields(
          [&](const std::string& field) { return core::outputSelected(scene.output.fields, field, materials); });
    for (const auto& f : fields) ptrs.push_back(&f);
    core::ParticleOutput parts;
    if (sides.solid) parts = core::selectParticles(sides.solid->particleOutput(), scene.output.fields);
    out.writeFields(n, t, ptrs, sides.solid ? &parts : nullptr);
    SideTotals solid, fluid;
    if (sides.solid) solid = sides.solid->totals();
    if (sides.fluid) fluid = sides.fluid->totals();
    if (!both) {  // each side trades its totals; the solid's writes the CSV of both
      const SideTotals peer = SideTotals::unpack(transport.trade((sides.solid ? solid : fluid).pack(), "totals"));
      (sides.solid ? fluid : solid) = peer;
    }
    out.writeTotals(n, t, solid, fluid);
  };
  std::unique_ptr<core::CsvWriter> steps;
  if (scene.output.enabled && sides.solid) {
    std::vector<std::string> cols{"step", "time", "dt", "iterations", "converged", "compute_s", "exchange_s"};
    if (!both) cols.insert(cols.end(), {"peer_compute_s", "peer_exchange_s"});
    for (const auto& f : schedule->measuredFields()) cols.push_back("residual_" + f);
    const std::string path = scene.output.directory + "/" + scene.name + "_coupling.csv";
    if (resumed)
      core::CsvWriter::cutForResume(comm, path, static_cast<std::int64_t>(resumed->scalar("run.coupling_csv")));
    steps = std::make_unique<core::CsvWriter>(comm, path, cols, 0,
                                              resumed ? core::CsvWriter::Mode::Append : core::CsvWriter::Mode::Truncate);
  }
  // The probes' particles (output.probes): position and displacement at t = 0 and every step.
  const auto probes =
      sides.solid ? mpm::ProbeRecorder::fromScene(
                        sides.solid->solver(), resumed ? static_cast<std::int64_t>(resumed->scalar("run.probes_csv")) : -1)
                  : nullptr;

  // 1. Start (a restart then returns both sides, the schedule and the clock to the checkpoint;
  //    in an MPMD launch the two programs first agree that they resume the same step).
  const double latency = transport.measureLatency(200);  // MPMD: the leaders' message latency
  startCoupling(sides, transport);
  if (!both) {
    const double mine = resumed ? clock[1] : -1.0;
    const double theirs = transport.trade({mine}, "restart step")[0];
    if (mine != theirs) {
      auto what = [](double s) { return s < 0 ? std::string("a fresh start") : "step " + std::to_string(long(s)); };
      throw std::invalid_argument(label + ": this program resumes " + what(mine) + ", the peer program " + what(theirs) +
                                  " (`coupler run --restart PATH` gives both the checkpoints of one step)");
    }
  }
  core::StepCollapse collapse(scene.time.dt_collapse_fraction);
  double t = clock[0];
  long n = static_cast<long>(clock[1]), iterations = static_cast<long>(clock[2]),
       unconverged = static_cast<long>(clock[3]);
  if (resumed) collapse.resumeFirst(clock[4]);
  double computeTotal = 0;
  const double exchangeStart = transport.seconds();
  core::OutputSchedule outputs(scene.output.interval, scene.time.end);
  if (resumed) {
    if (sides.solid) sides.solid->loadCheckpoint(*resumed, "solid");
    if (sides.fluid) sides.fluid->loadCheckpoint(*resumed, "fluid");
    schedule->load(*resumed, "schedule");
    outputs.resume(resumed->get("run.outputs"));
  } else {
    if (outputs.due(t)) output(n, t);
    if (probes) probes->record(sides.solid->solver());
  }
  auto checkpoint = [&](bool last) {
    if (!checkpoints.due(t, last)) return;
    core::CheckpointData data;
    if (sides.solid) sides.solid->saveCheckpoint(data, "solid");
    if (sides.fluid) sides.fluid->saveCheckpoint(data, "fluid");
    schedule->save(data, "schedule");
    data.put("run.coupled", std::vector<double>{t, double(n), double(iterations), double(unconverged), collapse.first()});
    data.put("run.outputs", outputs.position());
    out.save(data);
    data.put("run.coupling_csv", static_cast<double>(steps ? steps->length() : 0));
    data.put("run.probes_csv", static_cast<double>(probes ? probes->csvLength() : 0));
    checkpoints.write(data, t, n);
  };

  // 2. Steps.
  for (;;) {
    if (core::reached(t, scene.time.end)) break;
    const bool more = core::goesOn(t, n, scene.time.end, scene.time.max_steps);
    if (!(transport.trade({more ? 1.0 : 0.0}, "go on")[0] != 0.0 && more)) break;
    const double wall0 = now(), exchange0 = transport.seconds();
    const double inf = std::numeric_limits<double>::infinity();
    const double solidStep = sides.solid ? sides.solid->stableTimeStep() : inf;
    const double fluidStep = sides.fluid ? sides.fluid->stableTimeStep() : inf;
    const double mine = std::min(solidStep, fluidStep);
    const double theirs = transport.trade({mine}, "time step")[0];
    const double stable = std::min({mine, theirs, scene.time.dt_max});
    if (collapse.collapsed(stable)) {  // the same verdict on both sides: every rank of both throws
      std::string limit = "the peer program's stable step (its own message names the cell or particle)";
      if (stable == scene.time.dt_max)
        limit = "time.dt_max";
      else if (solidStep == stable)
        limit = sides.solid->solver().stableTimeStepLimit();
      else if (fluidStep == stable)
        limit = sides.fluid->solver().stableTimeStepLimit();
      const std::string what = collapse.message(stable, t, n + 1, limit);
      throw core::HealthError(both ? what : label + ": " + what, comm.root());
    }
    const double dt = core::landOn(t, stable, scene.time.end);
    const char* dtBy =
        core::stepSetBy(dt, stable, scene.time.dt_max, solidStep, fluidStep, sides.solid != nullptr);
    if (scene.time.dt_min > 0 && dt < scene.time.dt_min) {
      std::ostringstream os;
      os << label << ": time step " << dt << " s at t = " << t << " s (step " << n + 1
         << ") fell below time.dt_min = " << scene.time.dt_min << " s";
      throw std::runtime_error(os.str());
    }
    const StepReport r = schedule->step(sides, transport, dt);
    t += dt;
    ++n;
    LaunchWatchdog::step(n);
    if (afterStep) afterStep(n);
    if (sides.solid && comm.root() && sides.solid->solver().removedLastStep() > 0)
      log << sides.solid->solver().removalReport() << "\n" << std::flush;
    const double exchangeStep = transport.seconds() - exchange0;
    const auto peerSplit =
        checkHealth(sides, transport, comm, label, !both, {now() - wall0 - exchangeStep, exchangeStep});
    const double exchange = transport.seconds() - exchange0, compute = now() - wall0 - exchange;
    computeTotal += compute;
    iterations += r.iterations;
    if (!r.converged) {
      ++unconverged;
      if (comm.root() && sides.solid)
        log << "coupling: step " << n << " accepted unconverged after " << r.iterations
            << " iterations (coupling.accept_unconverged)\n";
    }
    if (steps) {
      std::vector<double> row{double(n), t, dt, double(r.iterations), r.converged ? 1.0 : 0.0, compute, exchange};
      if (!both) row.insert(row.end(), peerSplit.begin(), peerSplit.end());
      row.insert(row.end(), r.residuals.begin(), r.residuals.end());
      steps->row(row);
    }
    if (probes) probes->record(sides.solid->solver());
    if (outputs.due(t)) output(n, t);
    core::Progress::Extras extras{{"iters", double(r.iterations)}, {"iters_total", double(iterations)}};
    if (sides.fluid && sides.fluid->solver().semiImplicit())
      extras.emplace_back("lin_iters", double(sides.fluid->solver().linearIterations()));
    const bool last = !core::goesOn(t, n, scene.time.end, scene.time.max_steps);
    progress.step(static_cast<int>(n), t, dt, extras, last && sides.solid,  // the solid prints the last step always
                  std::string("dt_by=") + dtBy);
    if (last && !outputs.written(t) && outputs.due(t, true)) output(n, t);  // the last step
    checkpoint(last);
  }
  // 3. The last step is always written.
  if (!outputs.written(t) && outputs.due(t, true)) output(n, t);
  // Both sides reached the end: a timed wait that names a peer stopped after the last step,
  // before MPI_Finalize (which waits for every process without a bound of its own).
  transport.trade({1.0}, "the end of the run");

  record.completed();
  // 4. Closing lines.
  if (sides.solid) {
    const mpm::ParticleOutflow gone = sides.solid->solver().outflow();  // collective
    if (comm.root() && gone.count > 0) log << mpm::outflowSummary(gone) << std::flush;
    const auto& spread = sides.solid->solver().cells().spreadCooling();  // the same on every rank
    if (comm.root() && spread.cells > 0)
      log << "  solid heat: in " << spread.cells << " cell-steps (" << spread.steps << " steps) a cell's cooling was "
          << "beyond its solid's heat above " << mpm::kMinCellTemperatureShare << " of the material's mean temperature; " << -spread.energy
          << " J of it went to the whole material in proportion to the particles' thermal energy\n"
          << std::flush;
  }
  if (sides.fluid && sides.fluid->solver().viscous()) {
    const double heat = comm.sum(sides.fluid->solver().viscousHeat());  // collective
    if (comm.root())
      log << "  fluid viscous heat: " << heat << " J (the kinetic energy the fluids' viscosity turned into heat, this "
          << "process's steps)\n"
          << std::flush;
  }
  if (comm.root() && sides.solid) {
    log << "coupling: schedule " << core::name(scene.coupling.schedule) << ", " << iterations << " iterations in " << n
        << " steps (" << double(iterations) / double(std::max(1L, n)) << " per step), " << unconverged
        << " steps accepted unconverged\n";
  }
  if (comm.root()) {  // every process: its compute/exchange split and the mean time per exchange point
    const double ex = transport.seconds() - exchangeStart;
    const long points = transport.moves() + transport.trades();
    log << "coupling (" << label << "): computed " << computeTotal << " s, " << ex << " s in exchange ("
        << (both ? "in memory" : "rank to rank") << "; " << transport.moves() << " field moves and "
        << transport.trades() << " scalar trades, " << 1e6 * ex / double(std::max(1L, points))
        << " us each on average, waiting for the peer included)\n";
    if (!both)
      log << "coupling (" << label << "): message latency " << 1e6 * latency
          << " us (8 bytes each way between the leaders, median of 200 at the start)\n";
    log << "coupling (" << label << "): per exchange point (moves, mean wall time each, bytes each):";
    for (const auto& [tag, pt] : transport.points())
      log << " " << pt.what << " " << pt.moves << " x " << 1e6 * pt.seconds / double(std::max(1L, pt.moves))
          << " us, " << pt.bytes / std::max(1L, pt.moves) << " B;";
    log << "\n";
    if (sides.travel) {
      const long long cells = scene.mesh.numCells();
      log << "coupling (" << label << "): " << 8 * sides.travel->valuesPerCell() * cells
          << " bytes exchanged per pass over the four points over the whole mesh (declared fields; "
          << 8 * FieldUses::everything(sides.solids()).valuesPerCell() * cells
          << " with every field and component); " << transport.bytes() / std::max(1L, n)
          << " bytes per step moved by this process (" << transport.bytes() << " in " << n << " steps)\n";
    }
  }
  if (comm.root() && sides.fluid && sides.fluid->solver().semiImplicit()) {
    log << sides.fluid->solver().pressureSolveSummary(n) << "\n";
  }
  if (both)
    progress.finish(static_cast<int>(n), t, double(scene.mesh.numCells()));
  else if (sides.solid)
    progress.finish(static_cast<int>(n), t, double(particles), "particle-steps");
  else
    progress.finish(static_cast<int>(n), t, double(scene.mesh.numCells()), "cell-steps");
  return 0;
}

}  // namespace mpmice::coupler
