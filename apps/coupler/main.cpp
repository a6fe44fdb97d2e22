// coupler: checks scenes (with the solvers' own start-up validation) and composes and runs the
// MPMD launch of the two solvers.
//
// Sample runs:  coupler check configs/sod.yaml
//               coupler run --dry-run configs/pressurized_cylinder.yaml
//               coupler --help, coupler run --help, coupler check --help, coupler --version
#include <iostream>
#include <string>
#include <vector>

#include "coupler/cli/command_line.h"
#include "ice/solver/startup_check.h"
#include "mpm/solver/startup_check.h"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  // `coupler check` runs the start-up validation of the programs that would run the scene.
  const mpmice::coupler::StartupChecks checks = {{"mpm_solver", mpmice::mpm::validateStartup},
                                                 {"ice_solver", mpmice::ice::validateStartup}};
  return mpmice::coupler::runCommandLine(args, std::cout, std::cerr, checks);
}
