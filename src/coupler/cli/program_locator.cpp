#include "coupler/cli/program_locator.h"

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <unistd.h>

#ifndef MPMICE_MPIRUN_PATH
#define MPMICE_MPIRUN_PATH "mpirun"
#endif
#ifndef MPMICE_BIN_TO_LIBEXEC
#define MPMICE_BIN_TO_LIBEXEC "../libexec/mpmice"
#endif
#ifndef MPMICE_BIN_TO_LIB
#define MPMICE_BIN_TO_LIB "../lib"
#endif

namespace mpmice::coupler {

namespace fs = std::filesystem;

namespace {

bool isExecutableFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0;
}

std::string onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::istringstream dirs(path);
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && isExecutableFile(fs::path(dir) / program)) return (fs::path(dir) / program).string();
  return {};
}

}  // namespace

std::string ownDirectory() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string(".") : exe.parent_path().string();
}

std::vector<std::string> programCandidates(const std::string& program, const std::string& binDir,
                                           const std::string& ownDir) {
  if (!binDir.empty())
    return {(fs::path(binDir) / program).string(), (fs::path(binDir) / program / program).string()};
  return {(fs::path(ownDir) / program).string(),
          (fs::path(ownDir).parent_path() / program / program).lexically_normal().string()};
}

std::string locateProgram(const std::string& program, const std::string& binDir, const std::string& ownDir) {
  const auto candidates = programCandidates(program, binDir, ownDir);
  for (const auto& c : candidates)
    if (isExecutableFile(c)) return c;
  if (binDir.empty())
    if (auto p = onPath(program); !p.empty()) return p;
  return binDir.empty() ? candidates.front() : candidates.back();  // a build directory by default
}

std::string locateAdapterLibrary(const std::string& binDir, const std::string& ownDir) {
  const std::string name = "libmpmiceFoamAdapter.so";
  const fs::path base = binDir.empty() ? fs::path(ownDir) : fs::path(binDir);
  const std::vector<fs::path> candidates = {
      binDir.empty() ? base.parent_path() / "adapters" / "openfoam" / name : base / "adapters" / "openfoam" / name,
      (base / MPMICE_BIN_TO_LIB / name).lexically_normal()};
  for (const auto& c : candidates)
    if (fs::is_regular_file(c)) return c.string();
  return candidates.front().string();
}

std::string locateLaunchHelper(const std::string& ownDir) {
  const fs::path installed = (fs::path(ownDir) / MPMICE_BIN_TO_LIBEXEC / "mpirun").lexically_normal();
  if (isExecutableFile(installed)) return installed.string();
  if (isExecutableFile(MPMICE_MPIRUN_PATH)) return MPMICE_MPIRUN_PATH;
  return "mpirun";
}

}  // namespace mpmice::coupler
