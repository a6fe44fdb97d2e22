#include "couplings/volume/monolithic/monolithic_run.h"

#include <stdexcept>

#include "coupler/transport/in_memory_transport.h"
#include "couplings/volume/run/volume_run.h"
#include "ice/solver/standalone_run.h"
#include "mpm/solver/standalone_run.h"

namespace mpmice::coupler {

int runMonolithic(const core::Scene& scene, const core::Comm& comm, std::ostream& log, const std::string& restart) {
  // A scene of one kind of material needs one solver: run it alone, and say so.
  if (scene.solids().empty() || scene.fluids().empty()) {
    const bool solids = !scene.solids().empty();
    if (comm.root())
      log << "mpmice: the scene has " << (solids ? "no fluid" : "no solid") << "; running "
          << (solids ? "MPM" : "ICE") << " alone (as " << (solids ? "mpm_solver" : "ice_solver") << " would)\n";
    return solids ? mpm::runStandalone(scene, comm, log, restart) : ice::runStandalone(scene, comm, log, restart);
  }
  mpm::MpmSolver mpm(scene, comm);
  ice::IceSolver ice(scene, comm);
  if (!(mpm.decomposition().cellBox(comm.rank()) == ice.ownedBox()))
    throw std::logic_error("mpmice: the MPM and ICE decompositions differ");
  SolidSide solid(mpm);
  FluidSide fluid(ice, scene);
  InMemoryTransport transport;
  const FieldUses travel = agree(scene, solidDeclaration(scene), fluidDeclaration(scene));
  return runVolumeCoupling(scene, {&solid, &fluid, &travel}, transport, comm, log, "mpmice", {}, restart);
}

}  // namespace mpmice::coupler
