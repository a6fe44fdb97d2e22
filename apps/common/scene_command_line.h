#pragma once
// The command line of the scene programs (mpm_solver, ice_solver, mpmice), parsed by CLI11:
//   <program> [--restart PATH] scene.yaml | --help | --version
// --restart PATH resumes from a checkpoint (output.checkpoint_interval writes them): PATH is a
// checkpoint file or an output directory, meaning its latest checkpoint (core/io/checkpoint.h).
// --help (usage, the program's description and sample runs) and --version
// ("<program> 0.1.0 (<git describe>)") print to stdout on world rank 0 and exit 0; a missing or
// extra argument, or an unknown option, prints the error and "usage: <program> scene.yaml" to
// stderr on world rank 0 and exits 2. MPI is started before (every rank parses the same argv).
#include <CLI/CLI.hpp>

#include <iostream>
#include <optional>
#include <string>

#include "core/version.h"

namespace mpmice::apps {

struct SceneCommandLine {
  std::string scene;      // the scene file, when the program is to run
  std::string restart;    // --restart PATH ("" = a fresh start)
  std::optional<int> exit;  // set: exit with this status (help, version or an error was printed)
};

inline SceneCommandLine parseSceneCommandLine(int argc, char** argv, bool root, const std::string& program,
                                              const std::string& description, const std::string& samples) {
  SceneCommandLine line;
  CLI::App app(description, program);
  app.set_help_flag("-h,--help", "print this help and exit");
  app.set_version_flag("-V,--version", core::versionLine(program), "print the version and exit");
  app.add_option("scene.yaml", line.scene, "the scene file (YAML; docs/scene-reference.md)")->required();
  app.add_option("--restart", line.restart,
                 "resume from a checkpoint: a <base>_checkpoint_<step>.h5 file, or an output directory "
                 "(its latest checkpoint); docs/output-format.md")
      ->type_name("PATH");
  app.get_formatter()->label("Usage", "usage");
  app.footer("Sample runs:\n" + samples);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    if (root) std::cout << app.help() << std::flush;
    line.exit = 0;
  } catch (const CLI::CallForVersion& e) {
    if (root) std::cout << e.what() << "\n" << std::flush;
    line.exit = 0;
  } catch (const CLI::ParseError& e) {
    if (root)
      std::cerr << program << ": " << e.what() << "\nusage: " << program << " scene.yaml\n"
                << "Run with --help for more information.\n" << std::flush;
    line.exit = 2;
  }
  return line;
}

}  // namespace mpmice::apps
