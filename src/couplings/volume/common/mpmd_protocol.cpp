#include "couplings/volume/common/mpmd_protocol.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <thread>


namespace mpmice::coupler {

namespace {
std::string timeKeys(const core::TimeSpec& t) {
  std::ostringstream o;
  o.precision(17);
  o << "cfl " << t.cfl << ", dt_max " << t.dt_max << ", dt_min " << t.dt_min << ", dt_initial " << t.dt_initial
    << ", max_steps " << t.max_steps << ", dt_collapse_fraction " << t.dt_collapse_fraction;
  return o.str();
}
}  // namespace

HandshakeSections mpmiceHandshakeSections(const core::Scene& s) {
  std::ostringstream mesh, mats;
  mesh.precision(17);
  mesh << s.mesh.describe() << " (origin " << s.mesh.origin()[0] << "," << s.mesh.origin()[1] << ","
       << s.mesh.origin()[2] << ")";
  for (const auto& m : s.materials)
    mats << m.name << ":" << (m.kind == core::MaterialKind::Solid ? "solid " + m.constitutive.type : "fluid") << "/"
         << m.eos.type << " ";
  return {{"mesh", mesh.str()},
          {"materials", mats.str()},
          {"scene hash (mesh, materials, boundary)", core::sceneHash(s)},
          {"schedule", std::string(core::name(s.coupling.schedule))},
          {"end time", std::to_string(s.time.end)},
          // Both sides stop, step and judge a collapse by the same rules (a difference would
          // let one side stop while the other waits).
          {"time", timeKeys(s.time)},
          {"exchanged fields",
           "solid state: mass velocity temperature specific_volume | pressure force: pressure_force pressure | "
           "Lagrangian momentum: lagrangian_momentum coupling_work | exchange increments: exchange_momentum exchange_energy"}};
}

FieldUses agreeExchange(const Participant& p, const core::Scene& scene, bool solid, const ExchangeDeclaration& mine) {
  const ExchangeDeclaration theirs = decodeDeclaration(tradeWithPeer(p, encodeDeclaration(mine), "exchange declaration"));
  return solid ? agree(scene, mine, theirs) : agree(scene, theirs, mine);
}

namespace {
/// True when the environment's `variable` is "<p's name>:<step>".
bool faultAt(const char* variable, const Participant& p, long step) {
  const char* spec = std::getenv(variable);
  if (!spec) return false;
  const std::string s(spec);
  const auto colon = s.find(':');
  return colon != std::string::npos && s.substr(0, colon) == p.name() && std::atol(s.c_str() + colon + 1) == step;
}
}  // namespace

void maybeInjectFault(const Participant& p, long step) {
  if (faultAt("MPMICE_FAULT_EXIT", p, step)) {
    std::fprintf(stderr, "%s: MPMICE_FAULT_EXIT: exiting abruptly after step %ld\n", p.name().c_str(), step);
    std::fflush(stderr);
    std::_Exit(9);
  }
  if (faultAt("MPMICE_FAULT_STALL", p, step)) {  // a program that stops answering (alive, never back)
    std::fprintf(stderr, "%s: MPMICE_FAULT_STALL: sleeping for ever after step %ld\n", p.name().c_str(), step);
    std::fflush(stderr);
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
  }
}

}  // namespace mpmice::coupler
