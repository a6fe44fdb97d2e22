#include "coupler/cli/check_command.h"

#include <sstream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "coupler/cli/command_line.h"
#include "coupler/cli/run_command.h"
#include "core/scene/resource_estimate.h"
#include "core/version.h"

namespace mpmice::coupler {

std::string summarizeScene(const core::Scene& s) {
  std::string text = "scene '" + s.name + "': " + s.mesh.describe() + "; ";
  text += std::to_string(s.materials.size()) + (s.materials.size() == 1 ? " material (" : " materials (");
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    const auto& m = s.materials[i];
    const bool solid = m.kind == core::MaterialKind::Solid;
    text += (i ? ", " : "") + m.name + ": " + (solid ? "solid " + m.constitutive.type : "fluid " + m.eos.type);
  }
  text += "); " + std::to_string(s.geometry.size()) + " geometry object" + (s.geometry.size() == 1 ? "" : "s");
  std::ostringstream end;
  end << s.time.end;
  text += "; end time " + end.str() + " s";
  text += "; coupling " + std::string(core::name(s.coupling.schedule)) + " with " + std::string(core::name(s.coupling.fluid));
  text += "; needs " + core::estimateResources(s).describe();
  text += "; hash " + core::sceneHash(s);
  return text;
}

namespace {

constexpr const char* kCheckDescription =
    "Validates a scene without starting any solver: prints the scene as understood (every default "
    "filled in; itself a valid scene) and a one-line summary as a YAML comment, so the output can be "
    "saved and run. Exit 0 if valid; on an invalid scene the error (file, line, key, value, what was "
    "expected) goes to stderr and the exit status is 2.";

/// The `coupler check` command line (CLI11), bound to `quiet` and `file`.
void describeCheck(CLI::App& app, bool& quiet, std::string& file) {
  app.description(kCheckDescription);
  app.get_formatter()->label("Usage", "usage");
  app.set_help_flag("-h,--help", "print this help and exit");
  app.set_version_flag("-V,--version", core::versionLine("coupler"), "print the version and exit");
  app.add_flag("-q,--quiet", quiet, "print the summary line only");
  app.add_option("scene.yaml", file, "the scene file")->required();
  app.footer("Sample runs:\n"
             "  coupler check configs/sod.yaml\n"
             "  coupler check --quiet configs/pressurized_cylinder.yaml\n");
}

/// The first start-up rule a program of the scene's launch breaks, as the line to print ("" if none).
std::string startupRefusal(const core::Scene& scene, const std::string& file, const StartupChecks& checks) {
  for (const std::string& program : composeLaunch(scene, file, ".", "mpirun", 1, 1, "case").programs) {
    const auto check = checks.find(program);
    if (check == checks.end()) continue;
    try {
      check->second(scene);
    } catch (const std::invalid_argument& e) {
      // Messages of rules that know their line start "<file>:<line>:<column>: "; keep that place first.
      std::string what = e.what(), where = file;
      if (what.rfind(file + ":", 0) == 0) {
        const std::size_t end = what.find(": ", file.size());
        if (end != std::string::npos) {
          where = what.substr(0, end);
          what = what.substr(end + 2);
        }
      }
      return where + ": " + program + " refuses the scene at start: " + what;
    }
  }
  return "";
}

}  // namespace

std::string checkUsage() {
  bool quiet = false;
  std::string file;
  CLI::App app("", "coupler check");
  describeCheck(app, quiet, file);
  return app.help();
}

int runCheck(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             const StartupChecks& checks) {
  bool quiet = false;
  std::string file;
  CLI::App app("", "coupler check");
  describeCheck(app, quiet, file);
  if (const auto done = parseSubcommand(app, args, "coupler check", "coupler check [--quiet] <scene.yaml>", out, err))
    return *done;
  try {
    const core::Scene scene = core::loadScene(file);
    if (const std::string refusal = startupRefusal(scene, file, checks); !refusal.empty()) {
      err << refusal << "\n";
      return 2;
    }
    if (!quiet) out << core::dumpScene(scene);
    out << "# ok: " << summarizeScene(scene) << "\n";
    return 0;
  } catch (const core::SceneError& e) {
    err << e.what() << "\n";
    return 2;
  }
}

}  // namespace mpmice::coupler
