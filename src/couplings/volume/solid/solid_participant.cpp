#include "couplings/volume/solid/solid_participant.h"

#include <chrono>
#include <utility>

#include <stdexcept>

#include "coupler/exchange/cell_exchange.h"
#include "couplings/volume/common/mpmd_protocol.h"
#include "couplings/volume/common/run_output.h"
#include "couplings/volume/common/implicit_iteration.h"
#include "couplings/volume/solid/solid_side.h"
#include "mpm/solver/probes.h"
#include "core/util/progress.h"

namespace mpmice::coupler {

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

int runSolidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log) {
  handshake(p, mpmiceHandshakeSections(scene));
  mpm::MpmSolver mpm(scene, p.local());
  SolidSide side(mpm);
  const core::Decomposition peer(scene.mesh, p.peerSize(), scene.periodic());
  const CellExchange ex(p, mpm.decomposition(), peer);
  auto& fields = side.fields();

  core::Progress progress(log, p.local(), 0.0, scene.time.end, core::ProgressOptions{2.0, 0});
  progress.start(scene.name + " (mpm_solver, coupled to '" + p.peerName() + "', " +
                     std::to_string(mpm.globalParticleCount()) + " particles)",
                 scene.mesh.describe(), p.local().size());
  RunOutput out(scene, p.local(), mpm.decomposition(), "_solid", true);

  auto output = [&](long n, double t) {
    const core::ParticleOutput parts = side.particleOutput();
    out.writeFields(n, t, {}, &parts);
    const SideTotals fluid = SideTotals::unpack(tradeValues(p, side.totals().pack(), "totals"));
    out.writeTotals(n, t, side.totals(), fluid);
  };
  // The exchange points of the partitioned schedules: A and C out, B and D in.
  auto sendAC = [&](const std::string& what) {
    for (std::size_t s = 0; s < fields.size(); ++s) {
      ex.send(std::as_const(fields[s]).a(), kTagA + 8 * int(s), "solid state of " + fields[s].name + what);
      ex.send({&fields[s].lagrangianMomentum}, kTagC + 8 * int(s), "Lagrangian momentum of " + fields[s].name + what);
    }
  };
  auto receiveBD = [&](const std::string& what) {
    for (std::size_t s = 0; s < fields.size(); ++s) {
      ex.receive(fields[s].b(), kTagB + 8 * int(s), "pressure force on " + fields[s].name + " (" + what + ")");
      ex.receive(fields[s].d(), kTagD + 8 * int(s), "exchange increments (" + what + ")");
    }
  };
  const bool monolithic = scene.coupling.schedule == "monolithic";
  std::unique_ptr<ImplicitIteration> implicit;
  if (scene.coupling.schedule.rfind("implicit", 0) == 0)
    implicit = std::make_unique<ImplicitIteration>(scene.coupling, p.local(),
                                                   scene.coupling.schedule == "implicit_parallel");
  const bool parallelOrder = scene.coupling.schedule == "explicit_parallel";
  std::unique_ptr<core::CsvWriter> steps;
  if (scene.output.enabled) {
    std::vector<std::string> cols{"step", "time", "dt", "iterations", "converged", "compute_s", "exchange_s"};
    if (implicit)
      for (const auto& f : implicit->measuredFields()) cols.push_back("residual_" + f);
    steps = std::make_unique<core::CsvWriter>(p.local(), scene.output.directory + "/" + scene.name + "_coupling.csv",
                                              cols);
  }
  // Start: the fluid takes the solids' initial cell state (and fits its fluids around them).
  side.beginStep(side.stableTimeStep());
  side.produceA();
  for (std::size_t s = 0; s < fields.size(); ++s)
    ex.send(std::as_const(fields[s]).a(), kTagA + 8 * int(s), "initial solid state of " + fields[s].name);
  receiveBD("the fluid's initial pressure");
  double t = 0;
  long n = 0;
  if (out.due(t)) output(n, t);
  // The probes' particles (output.probes): position and displacement at t = 0 and every step.
  const auto probes = mpm::ProbeRecorder::fromScene(mpm);
  if (probes) probes->record(mpm);
  while (t < scene.time.end * (1 - 1e-12)) {
    if (!agreeToGoOn(p, scene, n)) break;
    double compute = 0, exchange = 0, t0 = now();
    auto lap = [&](double& bucket) {
      const double t1 = now();
      bucket += t1 - t0;
      t0 = t1;
    };
    const double dt = agreeOnTimeStep(p, side.stableTimeStep(), t, scene);
    lap(exchange);
    StepReport report;
    if (monolithic) {
      side.beginStep(dt);
      side.produceA();
      lap(compute);
      for (std::size_t s = 0; s < fields.size(); ++s)
        ex.send(std::as_const(fields[s]).a(), kTagA + 8 * int(s), "solid state of " + fields[s].name);
      for (std::size_t s = 0; s < fields.size(); ++s)
        ex.receive(fields[s].b(), kTagB + 8 * int(s), "pressure force on " + fields[s].name);
      lap(exchange);
      side.consumeBProduceC();
      lap(compute);
      for (std::size_t s = 0; s < fields.size(); ++s)
        ex.send({&fields[s].lagrangianMomentum}, kTagC + 8 * int(s), "Lagrangian momentum of " + fields[s].name);
      for (std::size_t s = 0; s < fields.size(); ++s)
        ex.receive(fields[s].d(), kTagD + 8 * int(s), "exchange increments of " + fields[s].name);
      lap(exchange);
      side.consumeDFinishStep();
      lap(compute);
    } else if (implicit) {
      const auto cp = mpm.checkpoint();
      auto pass = [&](bool serialOrder) {
        if (!serialOrder) sendAC("");
        side.fullStep(dt);
        lap(compute);
        if (serialOrder) sendAC("");
        receiveBD("iteration");
        lap(exchange);
      };
      auto verdict = [&](bool done) { tradeValues(p, {done ? 1.0 : 0.0}, "verdict of the iteration"); };
      report = implicit->iterate(fields, t, pass, [&] { mpm.restore(cp); }, verdict);
    } else {  // explicit: serial (solid first) or parallel (both from the last step's values)
      const bool parallelNow = parallelOrder && n > 0;
      if (parallelNow) sendAC("");
      side.fullStep(dt);
      lap(compute);
      if (!parallelNow) sendAC("");
      receiveBD("step");
      lap(exchange);
    }
    t += dt;
    ++n;
    maybeInjectFault(p, n);
    if (steps) {
      std::vector<double> row{double(n), t, dt, double(report.iterations), report.converged ? 1.0 : 0.0, compute,
                              exchange};
      row.insert(row.end(), report.residuals.begin(), report.residuals.end());
      steps->row(row);
    }
    if (probes) probes->record(mpm);
    if (out.due(t)) output(n, t);
    progress.step(static_cast<int>(n), t, dt, {{"iters", double(report.iterations)}});
  }
  progress.finish(static_cast<int>(n), t, double(mpm.globalParticleCount()), "particle-steps");
  return 0;
}

}  // namespace mpmice::coupler
