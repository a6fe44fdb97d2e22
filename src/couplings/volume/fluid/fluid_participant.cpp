#include "couplings/volume/fluid/fluid_participant.h"

#include <stdexcept>
#include <utility>

#include "coupler/exchange/cell_exchange.h"
#include "couplings/volume/common/mpmd_protocol.h"
#include "couplings/volume/common/run_output.h"
#include "couplings/volume/fluid/fluid_side.h"
#include "core/util/progress.h"

namespace mpmice::coupler {

int runFluidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log) {
  handshake(p, mpmiceHandshakeSections(scene));
  const bool monolithic = scene.coupling.schedule == "monolithic";
  const bool implicit = scene.coupling.schedule.rfind("implicit", 0) == 0;
  ice::IceSolver ice(scene, p.local());
  FluidSide side(ice, scene);
  const core::Decomposition peer(scene.mesh, p.peerSize(), scene.periodic());
  const CellExchange ex(p, ice.decomposition(), peer);
  auto& fields = side.fields();

  core::Progress progress(log, p.local(), 0.0, scene.time.end, core::ProgressOptions{1e30, 0});
  RunOutput out(scene, p.local(), ice.decomposition(), "_fluid", false);
  auto output = [&](long n, double t) {
    const std::vector<core::Field> f = ice.outputFields();
    std::vector<const core::Field*> ptrs;
    for (const auto& x : f) ptrs.push_back(&x);
    out.writeFields(n, t, ptrs, nullptr);
    tradeValues(p, side.totals().pack(), "totals");
  };
  for (std::size_t s = 0; s < fields.size(); ++s)
    ex.receive(fields[s].a(), kTagA + 8 * int(s), "initial solid state of " + fields[s].name);
  side.start();
  // The exchange points of the partitioned schedules: A and C in, B and D out.
  auto receiveAC = [&](const std::string& what) {
    for (std::size_t s = 0; s < fields.size(); ++s) {
      ex.receive(fields[s].a(), kTagA + 8 * int(s), "solid state of " + fields[s].name + " (" + what + ")");
      ex.receive({&fields[s].lagrangianMomentum}, kTagC + 8 * int(s), "Lagrangian momentum (" + what + ")");
    }
  };
  auto sendBD = [&](const std::string& what) {
    for (std::size_t s = 0; s < fields.size(); ++s) {
      ex.send(std::as_const(fields[s]).b(), kTagB + 8 * int(s), "receipt of the pressure force (" + what + ")");
      ex.send(std::as_const(fields[s]).d(), kTagD + 8 * int(s), "receipt of exchange increments (" + what + ")");
    }
  };
  side.primeOutput();
  sendBD("the fluid's initial pressure");
  double t = 0;
  long n = 0;
  if (out.due(t)) output(n, t);
  while (t < scene.time.end * (1 - 1e-12)) {
    if (!agreeToGoOn(p, scene, n)) break;
    const double dt = agreeOnTimeStep(p, side.stableTimeStep(), t, scene);
    if (monolithic) {
      for (std::size_t s = 0; s < fields.size(); ++s)
        ex.receive(fields[s].a(), kTagA + 8 * int(s), "solid state of " + fields[s].name);
      side.consumeAProduceB(dt);
      for (std::size_t s = 0; s < fields.size(); ++s)
        ex.send(std::as_const(fields[s]).b(), kTagB + 8 * int(s), "receipt of the pressure force on " + fields[s].name);
      for (std::size_t s = 0; s < fields.size(); ++s)
        ex.receive({&fields[s].lagrangianMomentum}, kTagC + 8 * int(s), "Lagrangian momentum of " + fields[s].name);
      side.consumeCProduceD();
      for (std::size_t s = 0; s < fields.size(); ++s)
        ex.send(std::as_const(fields[s]).d(), kTagD + 8 * int(s), "receipt of exchange increments of " + fields[s].name);
      side.finishStep();
    } else if (implicit) {  // the solid side iterates and decides; repeat until it says done
      const auto cp = ice.checkpoint();
      for (;;) {
        receiveAC("iteration");
        side.fullStep(dt);
        sendBD("iteration");
        if (tradeValues(p, {0.0}, "verdict of the iteration")[0] != 0.0) break;
        ice.restore(cp);
      }
    } else {
      receiveAC("step");
      side.fullStep(dt);
      sendBD("step");
    }
    t += dt;
    ++n;
    maybeInjectFault(p, n);
    if (out.due(t)) output(n, t);
  }
  progress.finish(static_cast<int>(n), t, double(scene.mesh.numCells()), "cell-steps");
  return 0;
}

}  // namespace mpmice::coupler
