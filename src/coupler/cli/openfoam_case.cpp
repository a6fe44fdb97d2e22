#include "coupler/cli/openfoam_case.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/io/checkpoint.h"
#include "core/io/h5_file.h"
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

/// controlDict text with the top-level entry `key` set to `value` (appended when absent).
std::string withEntry(const std::string& text, const std::string& key, const std::string& value) {
  const std::regex entry("(^|\n)" + key + R"(\s+[^;]*;)");
  if (std::regex_search(text, entry)) return std::regex_replace(text, entry, "$1" + key + "  " + value + ";");
  return text + "\n" + key + "  " + value + ";\n";
}

std::string exact(double v) {
  std::ostringstream e;
  e.precision(17);
  e << v;
  return e.str();
}

/// The controlDict entries `coupler run` owns: the scene's end time (two-way: both sides run to
/// it; one-way: the fluid runs to it, then the solid relaxes under the last forces for as long
/// again) and, with checkpoints, 17 significant digits (a double read back exactly: the time
/// directories a restart starts from hold the fields as they were).
std::string withRunEntries(std::string text, const core::Scene& scene) {
  text = withEntry(text, "endTime", exact(scene.time.end));
  if (scene.output.checkpoint_interval > 0) text = withEntry(text, "writePrecision", "17");
  return text;
}

/// Whether `dst` is a case copy made by coupler run (marker file, or its adapter entry).
bool isOurCopy(const fs::path& dst) {
  return fs::exists(dst / kCopyMarker) ||
         core::readTextFile(dst / "system" / "controlDict").find("added by `coupler run`") != std::string::npos;
}

/// The case copy of the scene: <output.directory>/<case folder name>; its source case (absolute).
std::pair<fs::path, fs::path> caseFolders(const core::Scene& scene, const std::string& sceneFile) {
  fs::path src = scene.coupling.interface.openfoam_case;
  if (src.is_relative()) src = fs::absolute(fs::path(sceneFile)).parent_path() / src;
  return {src, fs::absolute(fs::path(scene.output.directory) / src.filename())};
}

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
    if (!isOurCopy(dst))
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
  const auto [src, dst] = caseFolders(scene, sceneFile);
  if (!fs::exists(src / "system" / "controlDict"))
    throw std::invalid_argument(where + ": coupling.interface.case: '" + iface.openfoam_case + "' (" + src.string() +
                                ") is not an OpenFOAM case: no system/controlDict there");
  const std::string lib = locateAdapterLibrary(binDir, ownDirectory());
  if (!fs::exists(lib))
    throw std::invalid_argument("coupler run: the OpenFOAM adapter " + lib +
                                " is not built or installed (needs OpenFOAM's headers: scripts/openfoam_headers.sh, then cmake; "
                                "--bin-dir names where to look)");
  copyCaseFresh(src, dst);
  const fs::path cd = dst / "system" / "controlDict";
  const std::string text = withFunctionObject(core::readTextFile(cd), adapterEntry(lib, fs::absolute(sceneFile).string()));
  std::ofstream(cd) << withRunEntries(text, scene);
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

std::string resumeOpenFoamCase(const core::Scene& scene, const std::string& sceneFile, const std::string& restart,
                               std::ostream& out) {
  const std::string checkpoint = core::resolveCheckpoint(restart, scene.name);
  const double t = core::H5File::open(checkpoint).root().readAttributeDouble("time").at(0);
  const fs::path dst = caseFolders(scene, sceneFile).second;
  const fs::path cd = dst / "system" / "controlDict";
  if (!fs::exists(cd))
    throw std::invalid_argument("coupler run --restart: the checkpoint " + checkpoint + " (t = " + exact(t) +
                                " s) resumes the OpenFOAM side from the case copy of the run that wrote it, " +
                                dst.string() + ", which does not exist");
  if (!isOurCopy(dst))
    throw std::invalid_argument("coupler run --restart: " + dst.string() +
                                " is not a case copy made by coupler run; refusing to run in it");
  // The time directory of the checkpoint's time (its name has controlDict's timePrecision digits).
  fs::path match;
  double best = 0;
  std::string times;
  for (const auto& e : fs::directory_iterator(dst)) {
    if (!e.is_directory()) continue;
    const std::string name = e.path().filename().string();
    char* end = nullptr;
    const double v = std::strtod(name.c_str(), &end);
    if (name.empty() || *end != '\0') continue;
    times += (times.empty() ? "" : " ") + name;
    const double d = std::abs(v - t);
    if (d <= 1e-6 * std::max(std::abs(t), 1e-300) && (match.empty() || d < best)) {
      match = e.path();
      best = d;
    }
  }
  if (match.empty())
    throw std::invalid_argument("coupler run --restart: the checkpoint " + checkpoint + " is at t = " + exact(t) +
                                " s but the OpenFOAM case copy " + dst.string() +
                                " has no time directory of that time (it has: " + (times.empty() ? "none" : times) +
                                "); the fluid cannot resume there: choose a checkpoint whose time directory exists");
  // startTime: the checkpoint's time to the last digit. OpenFOAM finds the directory by the
  // time's name (timePrecision digits) and, the names agreeing, keeps this value as its clock
  // (not the directory's uniform/time value), so the clock goes on as in the uninterrupted run.
  std::string text = withEntry(core::readTextFile(cd), "startFrom", "startTime");
  text = withEntry(text, "startTime", exact(t));
  std::ofstream(cd) << withRunEntries(text, scene);
  out << "coupler: " << scene.coupling.interface.openfoam_solver << " resumes from " << match.string() << " (the time of "
      << checkpoint << ")\n"
      << std::flush;
  return dst.string();
}

}  // namespace mpmice::coupler
