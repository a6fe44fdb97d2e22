#pragma once
/// @brief The `coupler` command line: picks the subcommand and prints usage.
///
/// Subcommands: `check <scene.yaml>` (check_command.h), `run <scene.yaml>` (run_command.h). `coupler --help` prints usage and
/// returns 0, `coupler --version` the version line; each subcommand parses its own options with
/// CLI11 and answers --help and --version. No subcommand or an unknown one prints usage to `err` and returns 2. Nothing here
/// initialises MPI.
#include <ostream>
#include <string>
#include <vector>

namespace mpmice::coupler {

/// Runs the command line `args` (without the program name); returns the exit status.
int runCommandLine(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// The usage text.
std::string usage();

}  // namespace mpmice::coupler
