#pragma once
/// @brief The `coupler` command line: picks the subcommand and prints usage.
///
/// Subcommands: `check <scene.yaml>` (check_command.h), `run <scene.yaml>` (run_command.h). `coupler --help` prints usage and
/// returns 0, `coupler --version` the version line; each subcommand parses its own options with
/// CLI11 and answers --help and --version. No subcommand or an unknown one prints usage to `err` and returns 2. Nothing here
/// initialises MPI.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "coupler/cli/check_command.h"

namespace CLI {
class App;
}

namespace mpmice::coupler {

/// Parses a subcommand's `args` with its described CLI11 `app`. Returns the exit status when the
/// parse ends the command (--help, --version: 0; a bad option: 2 with `usageLine` on `err`), or
/// nothing when the command should go on.
std::optional<int> parseSubcommand(CLI::App& app, const std::vector<std::string>& args, const std::string& command,
                                   const std::string& usageLine, std::ostream& out, std::ostream& err);

/// Runs the command line `args` (without the program name); returns the exit status. `checks`:
/// the programs' start-up validation that `coupler check` runs (check_command.h).
int runCommandLine(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                   const StartupChecks& checks = {});

/// The usage text.
std::string usage();

}  // namespace mpmice::coupler
