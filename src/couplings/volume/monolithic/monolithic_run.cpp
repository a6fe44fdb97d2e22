#include "couplings/volume/monolithic/monolithic_run.h"

#include <stdexcept>

#include "coupler/transport/in_memory_transport.h"
#include "couplings/volume/run/volume_run.h"

namespace mpmice::coupler {

int runMonolithic(const core::Scene& scene, const core::Comm& comm, std::ostream& log) {
  mpm::MpmSolver mpm(scene, comm);
  ice::IceSolver ice(scene, comm);
  if (!(mpm.decomposition().cellBox(comm.rank()) == ice.ownedBox()))
    throw std::logic_error("mpmice: the MPM and ICE decompositions differ");
  SolidSide solid(mpm);
  FluidSide fluid(ice, scene);
  InMemoryTransport transport;
  return runVolumeCoupling(scene, {&solid, &fluid}, transport, comm, log, "mpmice");
}

}  // namespace mpmice::coupler
