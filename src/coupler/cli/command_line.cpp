#include "coupler/cli/command_line.h"

#include <CLI/CLI.hpp>

#include "coupler/cli/check_command.h"
#include "coupler/cli/run_command.h"
#include "core/scene/did_you_mean.h"
#include "core/version.h"

namespace mpmice::coupler {

std::optional<int> parseSubcommand(CLI::App& app, const std::vector<std::string>& args, const std::string& command,
                                   const std::string& usageLine, std::ostream& out, std::ostream& err) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return 0;
  } catch (const CLI::CallForVersion& e) {
    out << e.what() << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    err << command << ": " << e.what() << "\n"
        << "usage: " << usageLine << "\n"
        << "Run with --help for more information.\n";
    return 2;
  }
  return std::nullopt;
}

std::string usage() {
  return "usage: coupler <command> [options]\n"
         "\n"
         "Checks scenes and composes, prints and runs the MPMD launch of mpm_solver and ice_solver\n"
         "(or mpm_solver and OpenFOAM) on one scene. `coupler <command> --help` documents a command.\n"
         "\n"
         "commands:\n"
         "  check [--quiet] <scene.yaml>   validate a scene; print it as understood (defaults filled in)\n"
         "                                 and a one-line summary; exit 0 if valid, 2 if not\n"
         "  run [--mpm-ranks N] [--ice-ranks N] [--bin-dir DIR] [--dry-run] [--restart PATH] <scene.yaml>\n"
         "                                 compose, print and run the MPMD launch of mpm_solver and\n"
         "                                 ice_solver on the scene (ranks from coupling.ranks; the\n"
         "                                 programs beside this coupler, in its build tree or on PATH,\n"
         "                                 or in --bin-dir DIR: an installed bin or a build directory)\n"
         "\n"
         "options:\n"
         "  -h, --help                     this text\n"
         "  -V, --version                  print the version and exit\n"
         "\n"
         "Sample runs:\n"
         "  coupler check configs/sod.yaml\n"
         "  coupler run --dry-run configs/pressurized_cylinder.yaml\n"
         "  coupler --help\n";
}

int runCommandLine(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                   const StartupChecks& checks) {
  if (args.empty()) {
    err << "coupler: no command given\n\n" << usage();
    return 2;
  }
  const std::string& command = args.front();
  if (command == "-h" || command == "--help" || command == "help") {
    out << usage();
    return 0;
  }
  if (command == "-V" || command == "--version" || command == "version") {
    out << core::versionLine("coupler") << "\n";
    return 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (command == "check") return runCheck(rest, out, err, checks);
  if (command == "run") return runRun(rest, out, err);
  err << "coupler: unknown command '" << command << "'"
      << core::scene_detail::didYouMean(command, {"check", "run", "help"}) << "\n\n"
      << usage();
  return 2;
}

}  // namespace mpmice::coupler
