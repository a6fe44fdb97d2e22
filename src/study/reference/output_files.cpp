#include "study/reference/output_files.h"

#include <filesystem>
#include <regex>
#include <stdexcept>

namespace mpmice::study {

namespace fs = std::filesystem;

namespace {
/// The file of `dir` matching `pattern` that sorts first (`last` false) or last (the step
/// numbers are zero-padded); "" when none does.
std::string endFile(const fs::path& dir, const std::string& pattern, bool last) {
  const std::regex re(pattern);
  std::string best;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (std::regex_match(n, re) && (best.empty() || (last ? n > best : n < best))) best = n;
  }
  return best.empty() ? "" : (dir / best).string();
}

fs::path folder(const std::string& dir) { return dir.empty() ? fs::path(".") : fs::path(dir); }
}  // namespace

LastOutput lastOutput(const std::string& dirName, const std::string& scene) {
  const fs::path dir = folder(dirName);
  LastOutput o;
  o.particles = endFile(dir, scene + "_[0-9]+\\.h5", true);
  o.grid = o.particles;
  if (o.particles.empty()) {
    o.particles = endFile(dir, scene + "_solid_[0-9]+\\.h5", true);
    o.grid = endFile(dir, scene + "_fluid_[0-9]+\\.h5", true);
  }
  if (o.particles.empty() || o.grid.empty())
    throw std::runtime_error("no output of scene '" + scene + "' in " + dir.string());
  return o;
}

OutputSpan outputSpan(const std::string& dirName, const std::string& scene) {
  OutputSpan o;
  o.last = lastOutput(dirName, scene);
  const fs::path dir = folder(dirName);
  o.firstParticles = endFile(dir, scene + "_[0-9]+\\.h5", false);
  o.firstGrid = o.firstParticles;
  if (o.firstParticles.empty()) {
    o.firstParticles = endFile(dir, scene + "_solid_[0-9]+\\.h5", false);
    o.firstGrid = endFile(dir, scene + "_fluid_[0-9]+\\.h5", false);
  }
  return o;
}

}  // namespace mpmice::study
