#include "couplings/volume/common/mpmd_protocol.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "coupler/launch/timed_wait.h"

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
          {"schedule", s.coupling.schedule},
          {"end time", std::to_string(s.time.end)},
          {"exchanged fields",
           "A: mass velocity temperature specific_volume | B: pressure_force pressure | C: lagrangian_momentum | "
           "D: exchange_momentum exchange_energy"}};
}

std::vector<double> tradeValues(const Participant& p, const std::vector<double>& mine, const std::string& what) {
  std::vector<double> theirs(mine.size(), 0.0);
  if (p.local().root()) {
    std::vector<MPI_Request> reqs(2);
    const int n = static_cast<int>(mine.size());
    MPI_Irecv(theirs.data(), n, MPI_DOUBLE, 0, kTradeTag, p.inter(), &reqs[0]);
    MPI_Isend(mine.data(), n, MPI_DOUBLE, 0, kTradeTag, p.inter(), &reqs[1]);
    waitAll(reqs, p.timeout(), p.peerName(), what);
  }
  MPI_Bcast(theirs.data(), static_cast<int>(theirs.size()), MPI_DOUBLE, 0, p.local().raw());
  return theirs;
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

bool agreeToGoOn(const Participant& p, const core::Scene& scene, long stepsTaken) {
  const bool more = !(scene.time.max_steps > 0 && stepsTaken >= scene.time.max_steps);
  return tradeValues(p, {more ? 1.0 : 0.0}, "go on")[0] != 0.0 && more;
}

double agreeOnTimeStep(const Participant& p, double mine, double t, const core::Scene& scene) {
  const double theirs = tradeValues(p, {mine}, "time step")[0];
  double dt = std::min({mine, theirs, scene.time.dt_max});
  if (t + dt > scene.time.end) dt = scene.time.end - t;
  return dt;
}

}  // namespace mpmice::coupler
