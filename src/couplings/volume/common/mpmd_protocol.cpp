#include "couplings/volume/common/mpmd_protocol.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>


namespace mpmice::coupler {

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
          {"exchanged fields",
           "solid state: mass velocity temperature specific_volume | pressure force: pressure_force pressure | "
           "Lagrangian momentum: lagrangian_momentum | exchange increments: exchange_momentum exchange_energy"}};
}

void maybeInjectFault(const Participant& p, long step) {
  static const char* spec = std::getenv("MPMICE_FAULT_EXIT");
  if (!spec) return;
  const std::string s(spec);
  const auto colon = s.find(':');
  if (colon == std::string::npos || s.substr(0, colon) != p.name()) return;
  if (std::atol(s.c_str() + colon + 1) != step) return;
  std::fprintf(stderr, "%s: MPMICE_FAULT_EXIT: exiting abruptly after step %ld\n", p.name().c_str(), step);
  std::fflush(stderr);
  std::_Exit(9);
}

}  // namespace mpmice::coupler
