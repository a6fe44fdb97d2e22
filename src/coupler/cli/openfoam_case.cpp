#include "coupler/cli/openfoam_case.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "core/io/text_file.h"
#include "coupler/cli/process.h"
#include "coupler/cli/program_locator.h"

namespace mpmice::coupler {

namespace fs = std::filesystem;

std::string adapterEntry(const std::string& adapterLibrary, const std::string& sceneFile) {
  return "    // added by `coupler run`: the fluid side of the surface coupling\n"
         "    mpmiceAdapter\n    {\n        type    mpmiceAdapter;\n        libs    (\"" +
         adapterLibrary + "\");\n        scene   \"" + sceneFile + "\";\n    }\n";
}

std::string withFunctionObject(const std::string& text, const std::string& entry) {
  // The top-level `functions` keyword, then its opening brace (same or a later line).
  const std::regex key(R"((^|\n)functions\s*\{)");
  std::smatch m;
  if (std::regex_search(text, m, key)) {
    const auto at = static_cast<std::size_t>(m.position(0) + m.length(0));
    return text.substr(0, at) + "\n" + entry + text.substr(at);
  }
  return text + "\nfunctions\n{\n" + entry + "}\n";
}

namespace {

/// Whether `inner` is `outer` or lies inside it (both absolute and normalised).
bool within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
    if (o->empty()) continue;  // a trailing separator
    else if (i == inner.end() || *i != *o) return false;
  return true;
}

fs::path normalised(const fs::path& p) {
  std::error_code ec;
  const fs::path c = fs::weakly_canonical(fs::absolute(p), ec);
  return (ec ? fs::absolute(p) : c).lexically_normal();
}

constexpr const char* kCopyMarker = ".mpmice_case_copy";

}  // namespace

void copyCaseFresh(const fs::path& source, const fs::path& target) {
  const fs::path src = normalised(source), dst = normalised(target);
  if (within(dst, src) || within(src, dst))
    throw std::invalid_argument("coupler run: the OpenFOAM case copy " + dst.string() +
                                (dst == src ? " is" : within(dst, src) ? " lies inside" : " contains") +
                                " the source case " + src.string() +
                                "; refusing to overwrite it: set output.directory to a folder of its own (e.g. output)");
  if (fs::exists(dst)) {
    // Only an earlier copy of `coupler run` (marker file, or its adapter entry) is replaced.
    const bool ours = fs::exists(dst / kCopyMarker) ||
                      core::readTextFile(dst / "system" / "controlDict").find("added by `coupler run`") != std::string::npos;
    if (!ours)
      throw std::invalid_argument("coupler run: " + dst.string() +
                                  " exists and is not a case copy made by coupler run; refusing to delete it: move it "
                                  "away or set output.directory to another folder");
    fs::remove_all(dst);
  }
  fs::create_directories(dst.parent_path());
  fs::copy(src, dst, fs::copy_options::recursive);
  std::ofstream(dst / kCopyMarker) << "a copy of " << src.string() << " made by coupler run; replaced by the next run\n";
}

std::string prepareOpenFoamCase(const core::Scene& scene, const std::string& sceneFile, const std::string& binDir,
                                std::ostream& out) {
  const auto& iface = scene.coupling.interface;
  const std::string where = iface.where.str();
  fs::path src = iface.openfoam_case;
  if (src.is_relative()) src = fs::absolute(fs::path(sceneFile)).parent_path() / src;
  if (!fs::exists(src / "system" / "controlDict"))
    throw std::invalid_argument(where + ": coupling.interface.case: '" + iface.openfoam_case + "' (" + src.string() +
                                ") is not an OpenFOAM case: no system/controlDict there");
  const std::string lib = locateAdapterLibrary(binDir, ownDirectory());
  if (!fs::exists(lib))
    throw std::invalid_argument("coupler run: the OpenFOAM adapter " + lib +
                                " is not built or installed (needs OpenFOAM's headers: scripts/openfoam_headers.sh, then cmake; "
                                "--bin-dir names where to look)");
  const fs::path dst = fs::absolute(fs::path(scene.output.directory) / src.filename());
  copyCaseFresh(src, dst);
  const fs::path cd = dst / "system" / "controlDict";
  std::string text = withFunctionObject(core::readTextFile(cd), adapterEntry(lib, fs::absolute(sceneFile).string()));
  {
    // One end time: the scene's (two-way: both sides run to it; one-way: the fluid runs to it,
    // then the solid relaxes under the last forces for as long again).
    std::ostringstream e;
    e.precision(17);
    e << "$1endTime         " << scene.time.end << ";";
    text = std::regex_replace(text, std::regex(R"((^|\n)endTime\s+[^;]*;)"), e.str());
  }
  std::ofstream(cd) << text;
  if (!fs::exists(dst / "constant" / "polyMesh" / "points") && !fs::exists(dst / "constant" / "polyMesh" / "points.gz")) {
    out << "coupler: blockMesh -case " << dst.string() << "\n" << std::flush;
    const int status = runToFile({"blockMesh", "-case", dst.string()}, (dst / "log.blockMesh").string(),
                                 {"WM_PROJECT_DIR=/usr/share/openfoam"});
    if (status != 0) {
      std::string log = core::readTextFile(dst / "log.blockMesh");
      if (log.size() > 2000) log = log.substr(log.size() - 2000);
      throw std::runtime_error("coupler run: blockMesh failed for " + dst.string() + ":\n" + log);
    }
  }
  return dst.string();
}

}  // namespace mpmice::coupler
