#include "mpmice/solid/solid_participant.h"

#include <chrono>
#include <utility>

#include <stdexcept>

#include "exchange/cell_exchange.h"
#include "mpmice/common/mpmd_protocol.h"
#include "mpmice/common/run_output.h"
#include "mpmice/solid/solid_side.h"
#include "util/progress.h"

namespace mpmice::coupler {

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

int runSolidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log) {
  handshake(p, mpmiceHandshakeSections(scene));
  if (scene.coupling.schedule != "monolithic")
    throw std::invalid_argument("coupling.schedule '" + scene.coupling.schedule +
                                "' runs in the monolithic driver (mpmice) so far; the MPMD launch of mpm_solver + "
                                "ice_solver runs 'monolithic'");
  mpm::MpmSolver mpm(scene, p.local());
  SolidSide side(mpm);
  const core::Decomposition peer(scene.mesh, p.peerSize(), scene.periodic());
  const CellExchange ex(p, mpm.decomposition(), peer);
  auto& fields = side.fields();

  core::Progress progress(log, p.local(), 0.0, scene.time.end);
  progress.start(scene.name + " (mpm_solver, coupled to '" + p.peerName() + "', " +
                     std::to_string(mpm.globalParticleCount()) + " particles)",
                 scene.mesh.describe(), p.local().size());
  RunOutput out(scene, p.local(), mpm.decomposition(), "_solid", true);
  std::unique_ptr<core::CsvWriter> steps;
  if (scene.output.enabled)
    steps = std::make_unique<core::CsvWriter>(p.local(), scene.output.directory + "/" + scene.name + "_coupling.csv",
                                              std::vector<std::string>{"step", "time", "dt", "iterations",
                                                                       "compute_s", "exchange_s"});
  auto output = [&](long n, double t) {
    const core::ParticleOutput parts = side.particleOutput();
    out.writeFields(n, t, {}, &parts);
    const SideTotals fluid = SideTotals::unpack(tradeValues(p, side.totals().pack(), "totals"));
    out.writeTotals(n, t, side.totals(), fluid);
  };
  // Start: the fluid takes the solids' initial cell state (and fits its fluids around them).
  side.beginStep(side.stableTimeStep());
  side.produceA();
  for (std::size_t s = 0; s < fields.size(); ++s)
    ex.send(std::as_const(fields[s]).a(), kTagA + 8 * int(s), "initial solid state of " + fields[s].name);
  double t = 0;
  long n = 0;
  if (out.due(t)) output(n, t);
  while (t < scene.time.end * (1 - 1e-12)) {
    const bool more = !(scene.time.max_steps > 0 && n >= scene.time.max_steps);
    if (tradeValues(p, {more ? 1.0 : 0.0}, "go on")[0] == 0.0 || !more) break;
    double compute = 0, exchange = 0, t0 = now();
    auto lap = [&](double& bucket) {
      const double t1 = now();
      bucket += t1 - t0;
      t0 = t1;
    };
    const double dt = agreeOnTimeStep(p, side.stableTimeStep(), t, scene);
    lap(exchange);
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
      ex.receive({&fields[s].exchangeMomentum}, kTagD + 8 * int(s), "exchange increments of " + fields[s].name);
    lap(exchange);
    side.consumeDFinishStep();
    lap(compute);
    t += dt;
    ++n;
    maybeInjectFault(p, n);
    if (steps) steps->row({double(n), t, dt, 1.0, compute, exchange});
    if (out.due(t)) output(n, t);
    progress.step(static_cast<int>(n), t, dt, {{"iters", 1}});
  }
  progress.finish(static_cast<int>(n), t, double(mpm.globalParticleCount()), "particle-steps");
  return 0;
}

}  // namespace mpmice::coupler
