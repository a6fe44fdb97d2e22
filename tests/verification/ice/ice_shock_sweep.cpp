// The full ICE shock sweep (not a ctest): Toro's tests 1-5 and water against air at the real
// density ratio at 100..1600 cells for one ICE setting, printing L1(rho) against the exact
// solution, the fitted order, the overshoot behind each shock (% of the jump) and the stationary
// contact's velocity. scripts/ice_shock_sweep.sh runs it for every setting (docs/ice.md).
//   ice_shock_sweep [--advection A] [--limiter L] [--pressure P] [--face-pressure riemann|average]
//                   [--equilibrium fixed_energy|with_work] [--theta W] [--trace-mass-fraction Y] [--cfl C] [--cells 100,200,...] [--cases toro,water_air | sod,toro1,...,toro5,water_air,water_rarefaction,water_piston,air_shock,water_fan,moving_contact | neighbours,lax,slow_shock,...]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "ice_shock_cases.h"
#include "core/parallel/mpi_session.h"
#include "test_comm.h"

namespace {
mpmice::core::Comm g_comm;
}
const mpmice::core::Comm& mpmice::test::comm() { return g_comm; }

using namespace mpmice;

int main(int argc, char** argv) {
  test::TubeOptions o;
  std::vector<int> cells = {100, 200, 400, 800, 1600};
  std::string cases = "toro,water_air";
  for (int a = 1; a + 1 < argc; a += 2) {
    const std::string k = argv[a], v = argv[a + 1];
    if (k == "--advection") o.advection = v;
    else if (k == "--limiter") o.limiter = v;
    else if (k == "--pressure") o.pressure = v;
    else if (k == "--cfl") o.cfl = std::atof(v.c_str());
    else if (k == "--cases") cases = v;
    else if (k == "--face-pressure") o.facePressure = v;
    else if (k == "--equilibrium") o.equilibrium = v;
    else if (k == "--theta") o.semiTheta = std::atof(v.c_str());  // ice.semi_implicit_theta
    else if (k == "--trace-mass-fraction") setenv("ICE_TRACE_MASS_FRACTION", v.c_str(), 1);  // water_air only
    else if (k == "--cells") {
      cells.clear();
      std::stringstream ss(v);
      std::string t;
      while (std::getline(ss, t, ',')) cells.push_back(std::atoi(t.c_str()));
    } else {
      std::fprintf(stderr, "ice_shock_sweep: unknown option %s\n", k.c_str());
      return 2;
    }
  }
  core::MpiSession mpi(argc, argv);
  g_comm = mpi.world();
  std::printf("setting: %s %s %s face_pressure %s equilibrium %s cfl %.2f theta %.2f\n", o.advection.c_str(),
              o.limiter.c_str(), o.pressure.c_str(), o.facePressure.c_str(), o.equilibrium.c_str(), o.cfl, o.semiTheta);
  std::vector<test::ShockCase> list;
  // "toro": Sod and Toro 1-5; otherwise the named cases (sod, toro1 .. toro5, water_air, water_rarefaction,
  // water_piston, air_shock, water_fan, moving_contact: docs/ice.md "Water-air: start-up or scheme").
  for (const auto& c : test::toroCases())
    if (cases.find("toro,") != std::string::npos || cases == "toro" || ("," + cases + ",").find("," + c.name + ",") != std::string::npos)
      list.push_back(c);
  if (cases.find("water_air") != std::string::npos) list.push_back(test::waterAirRealDensity());
  if (cases.find("water_rarefaction") != std::string::npos) list.push_back(test::waterRarefaction());
  if (cases.find("water_piston") != std::string::npos) list.push_back(test::waterPiston());
  if (cases.find("air_shock") != std::string::npos) list.push_back(test::airShock());
  if (cases.find("water_fan") != std::string::npos) list.push_back(test::waterFan());
  if (cases.find("moving_contact") != std::string::npos) list.push_back(test::movingContact());
  // "neighbours": every case of neighbourCases; or one by name.
  for (const auto& c : test::neighbourCases())
    if (cases.find("neighbours") != std::string::npos || ("," + cases + ",").find("," + c.name + ",") != std::string::npos)
      list.push_back(c);
  for (const auto& c : list) {
    std::vector<double> err;
    std::vector<int> ns;
    for (const int n : cells) {
      const test::ShockResult r = test::runShockCase(c, n, o);
      if (!r.completed) {
        std::printf("%-14s %5d cells: STOPPED (%s)\n", c.name.c_str(), n, r.error.c_str());
        continue;
      }
      std::printf("%-14s %5d cells: L1(rho) %.4e  overshoot rho %+.2f %% p %+.2f %%  contact |u-u*|/speed %.1e  steps %ld  created energy %.1e",
                  c.name.c_str(), n, r.l1, r.overRho, r.overP, r.contactU, r.steps, r.createdShare);
      if (c.twoMaterials) std::printf("  shocked material's own rho %+.2f %%", r.overRhoOwn);
      std::printf("\n");
      err.push_back(r.l1);
      ns.push_back(n);
    }
    if (err.size() >= 2) std::printf("%-14s fitted order %.2f\n", c.name.c_str(), test::fittedOrder(ns, err));
    std::fflush(stdout);
  }
  return 0;
}
