// coupler: checks scenes (and, later, composes and runs the MPMD launch of the two solvers).
//
// Sample runs:  coupler check configs/sod.yaml
//               coupler run --dry-run configs/pressurized_cylinder.yaml
//               coupler --help, coupler run --help, coupler check --help, coupler --version
#include <iostream>
#include <string>
#include <vector>

#include "coupler/cli/command_line.h"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  return mpmice::coupler::runCommandLine(args, std::cout, std::cerr);
}
