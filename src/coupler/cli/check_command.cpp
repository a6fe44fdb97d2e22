#include "coupler/cli/check_command.h"

#include <sstream>

#include "coupler/cli/command_line.h"
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

std::string checkUsage() {
  return "usage: coupler check [--quiet] <scene.yaml>\n"
         "\n"
         "Validates a scene without starting any solver: prints the scene as understood (every\n"
         "default filled in; itself a valid scene) and a one-line summary as a YAML comment, so the\n"
         "output can be saved and run. Exit 0 if valid; on an invalid scene the error (file, line,\n"
         "key, value, what was expected) goes to stderr and the exit status is 2.\n"
         "\n"
         "arguments:\n"
         "  <scene.yaml>                   the scene file\n"
         "\n"
         "options:\n"
         "  -q, --quiet                    print the summary line only\n"
         "  -h, --help                     this text\n"
         "  -V, --version                  print the version and exit\n"
         "\n"
         "Sample runs:\n"
         "  coupler check configs/sod.yaml\n"
         "  coupler check --quiet configs/pressurized_cylinder.yaml\n";
}

int runCheck(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  bool quiet = false;
  std::vector<std::string> files;
  for (const auto& a : args) {
    if (a == "--quiet" || a == "-q") {
      quiet = true;
    } else if (a == "-h" || a == "--help") {
      out << checkUsage();
      return 0;
    } else if (a == "-V" || a == "--version") {
      out << core::versionLine("coupler") << "\n";
      return 0;
    } else if (!a.empty() && a.front() == '-') {
      err << "coupler check: unknown option '" << a << "'\n\n" << usage();
      return 2;
    } else {
      files.push_back(a);
    }
  }
  if (files.size() != 1) {
    err << "coupler check: expected one scene file, got " << files.size() << "\n\n" << usage();
    return 2;
  }
  try {
    const core::Scene scene = core::loadScene(files.front());
    if (!quiet) out << core::dumpScene(scene);
    out << "# ok: " << summarizeScene(scene) << "\n";
    return 0;
  } catch (const core::SceneError& e) {
    err << e.what() << "\n";
    return 2;
  }
}

}  // namespace mpmice::coupler
