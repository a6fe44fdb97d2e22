// An installed mpmice used from outside its tree: read a scene, build the solid and the fluid
// side in this process, and take one coupled step of the scene's schedule over the in-memory
// transport (what mpmice does every step). Prints the step and the totals; exit 0 only when
// both clocks advanced by the step and the particles kept their mass.
//   coupled_step scene.yaml
#include <algorithm>
#include <cmath>
#include <iostream>

#include <mpmice/core/version.h>  // the namespaced form of "core/version.h"
#include "core/parallel/mpi_session.h"
#include "core/scene/scene.h"
#include "coupler/transport/in_memory_transport.h"
#include "couplings/volume/schedule/coupling_schedule.h"

using namespace mpmice;

int main(int argc, char** argv) {
  core::MpiSession session(argc, argv);
  if (argc != 2) {
    std::cerr << "usage: coupled_step scene.yaml\n";
    return 2;
  }
  const core::Comm comm = session.world();
  try {
    const core::Scene scene = core::loadScene(argv[1]);
    mpm::MpmSolver mpm(scene, comm);
    ice::IceSolver ice(scene, comm);
    coupler::SolidSide solid(mpm);
    coupler::FluidSide fluid(ice, scene);
    const coupler::Sides sides{&solid, &fluid};
    coupler::InMemoryTransport transport;
    coupler::startCoupling(sides, transport);
    const auto before = solid.totals();
    const double dt = std::min(solid.stableTimeStep(), fluid.stableTimeStep());
    const auto schedule = coupler::makeSchedule(scene, comm);
    const auto report = schedule->step(sides, transport, dt);
    const auto solidAfter = solid.totals();
    const auto fluidAfter = fluid.totals();
    std::cout.precision(10);
    std::cout << "consumer: " << core::versionLine("coupled_step") << "\n"
              << "consumer: scene '" << scene.name << "', schedule " << core::name(scene.coupling.schedule)
              << ", one step of " << dt << " s in " << report.iterations << " iteration(s)\n"
              << "consumer: solid t = " << mpm.time() << " s, mass " << solidAfter.mass << " kg; fluid t = "
              << ice.time() << " s, mass " << fluidAfter.mass << " kg\n";
    const bool ok = dt > 0 && mpm.time() == dt && ice.time() == dt && solidAfter.mass == before.mass &&
                    std::isfinite(fluidAfter.mass) && fluidAfter.mass > 0 && report.converged;
    std::cout << (ok ? "consumer: coupled step ok\n" : "consumer: FAILED\n");
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "coupled_step: " << e.what() << "\n";
    return 2;
  }
}
