#include "coupler/cli/check_command.h"

#include <sstream>

#include "coupler/cli/command_line.h"
#include "core/scene/resource_estimate.h"

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

int runCheck(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  bool quiet = false;
  std::vector<std::string> files;
  for (const auto& a : args) {
    if (a == "--quiet" || a == "-q") {
      quiet = true;
    } else if (a == "-h" || a == "--help") {
      out << usage();
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
