#include "couplings/volume/solid/solid_participant.h"

#include "coupler/transport/mpi_transport.h"
#include "couplings/volume/common/mpmd_protocol.h"
#include "couplings/volume/run/volume_run.h"

namespace mpmice::coupler {

int runSolidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log,
                        const std::string& restart) {
  handshake(p, mpmiceHandshakeSections(scene));
  const FieldUses travel = agreeExchange(p, scene, true, solidDeclaration(scene));
  mpm::MpmSolver mpm(scene, p.local());
  SolidSide side(mpm);
  const core::Decomposition peer(scene.mesh, p.peerSize(), scene.periodic());
  MpiTransport transport(p, mpm.decomposition(), peer);
  return runVolumeCoupling(scene, {&side, nullptr, &travel}, transport, p.local(), log,
                           "mpm_solver, coupled to '" + p.peerName() + "'", [&](long n) { maybeInjectFault(p, n); }, restart);
}

}  // namespace mpmice::coupler
