#include "couplings/volume/fluid/fluid_participant.h"

#include "coupler/transport/mpi_transport.h"
#include "couplings/volume/common/mpmd_protocol.h"
#include "couplings/volume/run/volume_run.h"

namespace mpmice::coupler {

int runFluidParticipant(const Participant& p, const core::Scene& scene, std::ostream& log,
                        const std::string& restart) {
  handshake(p, mpmiceHandshakeSections(scene));
  const FieldUses travel = agreeExchange(p, scene, false, fluidDeclaration(scene));
  ice::IceSolver ice(scene, p.local());
  FluidSide side(ice, scene);
  const core::Decomposition peer(scene.mesh, p.peerSize(), scene.periodic());
  MpiTransport transport(p, ice.decomposition(), peer);
  return runVolumeCoupling(scene, {nullptr, &side, &travel}, transport, p.local(), log,
                           "ice_solver, coupled to '" + p.peerName() + "'", [&](long n) { maybeInjectFault(p, n); }, restart);
}

}  // namespace mpmice::coupler
